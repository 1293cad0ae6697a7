# Another program's G-buffer in the real editor under Xvfb (issue 28): a `render --out` export
# dropped on the window, re-lit live with editable lights, closed again; bad inputs refused with one
# sentence each; `--gbuffer` with real mouse drags that must not move the fixed camera. See ui_gbuffer.sh.
gbl_xdotool_test(ui_gbuffer TIMEOUT 600)
