# The G-buffer layout combo with real X clicks (issue 12): the Pipeline window's combo opened and
# "packed" picked on the real editor under Xvfb; see ui_layout_combo.sh.
gbl_xdotool_test(ui_layout_combo)
