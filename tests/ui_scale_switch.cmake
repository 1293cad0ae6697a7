# View > UI scale switched up and down by real clicks while the editor runs: the frame stays drawn
# and no GL error is reported. See ui_scale_switch.sh.
gbl_xdotool_test(ui_scale_switch TIMEOUT 240)
