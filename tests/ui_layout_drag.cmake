# The tiled layout's boundaries dragged with real X input, kept in imgui.ini across a restart,
# and a bad saved line refused (issue 26). See ui_layout_drag.sh.
gbl_xdotool_test(ui_layout_drag TIMEOUT 240)
