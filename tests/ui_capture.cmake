# File > Capture a program... with real input under Xvfb (issue 49): tests/capture_target's deferred_demo
# captured from the editor's dialog and opened as its G-buffer; a program that does not exist is refused
# in one sentence and the editor keeps drawing. See ui_capture.sh.
gbl_xdotool_test(ui_capture TIMEOUT 300)
if(TEST ui_capture AND TARGET deferred_demo)
  set_property(TEST ui_capture APPEND PROPERTY ENVIRONMENT "GBL_DEFERRED_DEMO=$<TARGET_FILE:deferred_demo>")
endif()
