# The course view of the Lessons window with real X clicks (issue 27): progress kept across a restart of the editor
# under Xvfb, checked through --log-frames. See ui_course.sh.
gbl_xdotool_test(ui_course)
