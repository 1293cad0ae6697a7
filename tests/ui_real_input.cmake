# Real X input end to end (issue 11): xdotool taps, clicks and a double click on the real editor
# under Xvfb with slow frames, checked through --log-frames and the saved session. See ui_real_input.sh.
find_program(GBL_XVFB_RUN xvfb-run)
find_program(GBL_XDOTOOL xdotool)
if(GBL_XVFB_RUN AND GBL_XDOTOOL)
  add_test(NAME ui_real_input
    COMMAND ${GBL_XVFB_RUN} -a -s "-screen 0 1920x1080x24"
            sh ${CMAKE_CURRENT_SOURCE_DIR}/ui_real_input.sh $<TARGET_FILE:gbuffer-lab> ${CMAKE_CURRENT_BINARY_DIR}/ui_real_input)
  set_tests_properties(ui_real_input PROPERTIES LABELS "ui;gl" TIMEOUT 600
    PASS_REGULAR_EXPRESSION "ui_real_input: PASS" FAIL_REGULAR_EXPRESSION "ui_real_input: FAIL"
    SKIP_REGULAR_EXPRESSION "ui_real_input skipped")
else()
  add_test(NAME ui_real_input COMMAND ${CMAKE_COMMAND} -E echo
           "ui_real_input skipped: needs xvfb-run and xdotool (scripts/install-deps.sh installs both)")
  set_tests_properties(ui_real_input PROPERTIES LABELS "ui" SKIP_REGULAR_EXPRESSION "skipped")
endif()
