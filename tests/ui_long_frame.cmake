# The long-frame switch in the real editor (issue 25), under xvfb-run: tests/ui_long_frame_script.txt.
find_program(GBL_XVFB_RUN xvfb-run)
if(GBL_XVFB_RUN)
  add_test(NAME ui_long_frame
    COMMAND ${GBL_XVFB_RUN} -a -s "-screen 0 1920x1080x24"
            $<TARGET_FILE:gbuffer-lab> --ui-test ${CMAKE_CURRENT_SOURCE_DIR}/ui_long_frame_script.txt
            --size 1280x720 --no-vsync --frame-warn-seconds 0.000001
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(ui_long_frame PROPERTIES LABELS "ui;gl" TIMEOUT 600 FAIL_REGULAR_EXPRESSION "ui-test FAIL")
else()
  add_test(NAME ui_long_frame COMMAND ${CMAKE_COMMAND} -E echo "ui_long_frame skipped: xvfb-run not found (apt install xvfb)")
  set_tests_properties(ui_long_frame PROPERTIES LABELS "ui" SKIP_REGULAR_EXPRESSION "skipped")
endif()
