# The UI scale is kept in imgui.ini with the window layout; --ui-scale wins over it for
# its run, a bad saved value is reported and ignored. See ui_scale_saved.sh.
gbl_xdotool_test(ui_scale_saved TIMEOUT 180)
