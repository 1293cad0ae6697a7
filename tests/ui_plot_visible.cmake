# The attenuation plot in view without scrolling at 1280x720 and 1600x900. See ui_plot_visible.sh.
gbl_xdotool_test(ui_plot_visible TIMEOUT 120)
