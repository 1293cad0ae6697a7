# The docked layout with real X input: a window dragged by its tab into another's tab bar docks
# there as a tab, one dragged out floats, and imgui.ini keeps both across a restart. See ui_dock_drag.sh.
gbl_xdotool_test(ui_dock_drag TIMEOUT 240)
