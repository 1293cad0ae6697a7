# The scrubber and the A/B divider driven by real X events (issue 10), at 1280x720 and 1600x900,
# each on an Xvfb of its own (ui_teaching.sh starts them).
gbl_xdotool_test(ui_teaching OWN_XVFB)
