# Another program's G-buffer in the real editor under Xvfb (issue 28): a `render --out` export
# dropped on the window, re-lit live with editable lights, closed again; bad inputs refused with one
# sentence each; `--gbuffer` with real mouse drags that must not move the fixed camera; a manifest and a
# folder dropped by a real X drag-and-drop (tests/support/xdnd_drop.c). See ui_gbuffer.sh.
gbl_xdotool_test(ui_gbuffer TIMEOUT 600)
if(TARGET xdnd_drop)
  set_property(TEST ui_gbuffer APPEND PROPERTY ENVIRONMENT "GBL_XDND_DROP=$<TARGET_FILE:xdnd_drop>")
endif()
