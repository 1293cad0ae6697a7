# The attenuation plot's radius marker and ghost (issue 26) with real X input at 1280x720: a drag of
# Kq to the right moves the radius the plot marks, the ghost keeps the one before. See ui_plot_drag.sh.
gbl_xdotool_test(ui_plot_drag TIMEOUT 300)
