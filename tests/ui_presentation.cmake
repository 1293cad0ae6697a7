# The presentation layout entered and left by the P key and by View > Presentation, with and
# without a lesson, by real X input. See ui_presentation.sh.
gbl_xdotool_test(ui_presentation TIMEOUT 240)
