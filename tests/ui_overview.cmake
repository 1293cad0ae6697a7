# The viewport's attachment overview (issue 26) with real X input: a tap of G shows every attachment
# in a labelled grid, a click on a cell shows it full size. See ui_overview.sh.
gbl_xdotool_test(ui_overview TIMEOUT 300)
