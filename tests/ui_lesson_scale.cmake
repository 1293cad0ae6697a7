# A whole lesson at UI scale 1.5 at 1280x720 by real clicks, at least 12 lines of it in view on
# every step. See ui_lesson_scale.sh.
gbl_xdotool_test(ui_lesson_scale TIMEOUT 240)
