# UI scale kept with the window layout (issue 26): a saved scale comes back, --ui-scale wins for
# its run, a bad saved value is reported and ignored. See ui_scale_saved.sh.
find_program(GBL_XVFB_RUN xvfb-run)
if(GBL_XVFB_RUN)
  add_test(NAME ui_scale_saved
    COMMAND ${GBL_XVFB_RUN} -a -s "-screen 0 1280x720x24"
            sh ${CMAKE_CURRENT_SOURCE_DIR}/ui_scale_saved.sh $<TARGET_FILE:gbuffer-lab> ${CMAKE_CURRENT_BINARY_DIR}/ui_scale_saved)
  set_tests_properties(ui_scale_saved PROPERTIES LABELS "ui;gl" TIMEOUT 180
    PASS_REGULAR_EXPRESSION "ui_scale_saved: PASS" FAIL_REGULAR_EXPRESSION "ui-test FAIL|ui_scale_saved: FAIL")
else()
  add_test(NAME ui_scale_saved COMMAND ${CMAKE_COMMAND} -E echo "ui_scale_saved skipped: xvfb-run not found (apt install xvfb)")
  set_tests_properties(ui_scale_saved PROPERTIES LABELS "ui" SKIP_REGULAR_EXPRESSION "skipped")
endif()
