# Real X input end to end (issue 11): xdotool taps, clicks and a double click on the real editor
# under Xvfb with slow frames, checked through --log-frames and the saved session. See ui_real_input.sh.
gbl_xdotool_test(ui_real_input)
