# MSAA in the editor with real X clicks (issue 47): msaa 4 picked in the Pipeline window's combo,
# the complex-pixel overlay ticked, a viewer's sample selected, the inspector's samples; see ui_msaa.sh.
gbl_xdotool_test(ui_msaa)
