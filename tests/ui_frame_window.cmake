# The Frame window (issue 24) with real X input: xdotool clicks a pin, a pass and "Stop here" on the
# real editor under Xvfb, checked through --log-frames. See ui_frame_window.sh.
gbl_xdotool_test(ui_frame_window TIMEOUT 300)
