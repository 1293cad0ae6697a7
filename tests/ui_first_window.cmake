# The editor's first window without --size fits the screen: ui_first_window.sh.
gbl_xdotool_test(ui_first_window OWN_XVFB TIMEOUT 180)
