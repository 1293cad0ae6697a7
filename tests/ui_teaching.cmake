# The scrubber and the A/B divider driven by real X events (issue 10), at 1280x720 and 1600x900,
# each on an Xvfb of its own (ui_teaching.sh starts them).
find_program(GBL_XVFB_RUN xvfb-run)
find_program(GBL_XDOTOOL xdotool)
if(GBL_XVFB_RUN AND GBL_XDOTOOL)
  add_test(NAME ui_teaching
    COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/ui_teaching.sh $<TARGET_FILE:gbuffer-lab> ${CMAKE_CURRENT_BINARY_DIR}/ui_teaching)
  set_tests_properties(ui_teaching PROPERTIES LABELS "ui;gl" TIMEOUT 600
    PASS_REGULAR_EXPRESSION "ui_teaching: PASS" FAIL_REGULAR_EXPRESSION "ui_teaching: FAIL"
    SKIP_REGULAR_EXPRESSION "ui_teaching skipped")
else()
  add_test(NAME ui_teaching COMMAND ${CMAKE_COMMAND} -E echo
           "ui_teaching skipped: needs xvfb-run and xdotool (scripts/install-deps.sh installs both)")
  set_tests_properties(ui_teaching PROPERTIES LABELS "ui" SKIP_REGULAR_EXPRESSION "skipped")
endif()
