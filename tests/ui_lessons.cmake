# The Lessons window with real X clicks (issue 10): Start, Next, Back and Leave on the real editor
# under Xvfb, checked through --log-frames, and screenshots of a lesson step. See ui_lessons.sh.
gbl_xdotool_test(ui_lessons)
