# The Frame window (issue 24) with real X input: xdotool clicks a pin, a pass and "Stop here" on the
# real editor under Xvfb, checked through --log-frames. See ui_frame_window.sh.
find_program(GBL_XVFB_RUN xvfb-run)
find_program(GBL_XDOTOOL xdotool)
if(GBL_XVFB_RUN AND GBL_XDOTOOL)
  add_test(NAME ui_frame_window
    COMMAND ${GBL_XVFB_RUN} -a -s "-screen 0 1920x1080x24"
            sh ${CMAKE_CURRENT_SOURCE_DIR}/ui_frame_window.sh $<TARGET_FILE:gbuffer-lab> ${CMAKE_CURRENT_BINARY_DIR}/ui_frame_window)
  set_tests_properties(ui_frame_window PROPERTIES LABELS "ui;gl" TIMEOUT 300
    PASS_REGULAR_EXPRESSION "ui_frame_window: PASS" FAIL_REGULAR_EXPRESSION "ui_frame_window: FAIL"
    SKIP_REGULAR_EXPRESSION "ui_frame_window skipped")
else()
  add_test(NAME ui_frame_window COMMAND ${CMAKE_COMMAND} -E echo
           "ui_frame_window skipped: needs xvfb-run and xdotool (scripts/install-deps.sh installs both)")
  set_tests_properties(ui_frame_window PROPERTIES LABELS "ui" SKIP_REGULAR_EXPRESSION "skipped")
endif()
