# A lesson step with the glass panes in the real editor: opening, Next, Back and Leave load the
# default scene with or without them (xdotool clicks under Xvfb). See ui_lesson_glass.sh.
gbl_xdotool_test(ui_lesson_glass)
