# The docked layout at UI scales 1, 1.5, 2 and 1.25, switched from the View menu by real clicks at
# 1280x720 and 1600x900: the viewport at least half the width, the strip fitted to its images,
# nothing cut off, the lesson's lines counted. See ui_scale_layouts.sh.
gbl_xdotool_test(ui_scale_layouts TIMEOUT 300)
