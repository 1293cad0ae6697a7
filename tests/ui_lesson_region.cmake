# The lesson region: at least 12 lines of a lesson's text in view at 1280x720 and 1600x900, by real
# clicks; the task hint does not take them; Leave restores the layout. See ui_lesson_region.sh.
gbl_xdotool_test(ui_lesson_region TIMEOUT 300)
