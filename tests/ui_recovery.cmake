# Crash recovery end to end (issue 6): an editor edits, autosaves and is killed with SIGKILL;
# the next one must offer the autosave and restoring it must bring the edits back. See ui_recovery.sh.
find_program(GBL_XVFB_RUN xvfb-run)
if(GBL_XVFB_RUN)
  add_test(NAME ui_recovery
    COMMAND ${GBL_XVFB_RUN} -a -s "-screen 0 1280x720x24"
            sh ${CMAKE_CURRENT_SOURCE_DIR}/ui_recovery.sh $<TARGET_FILE:gbuffer-lab> ${CMAKE_CURRENT_BINARY_DIR}/ui_recovery)
  set_tests_properties(ui_recovery PROPERTIES LABELS "ui;gl" TIMEOUT 600
    PASS_REGULAR_EXPRESSION "ui_recovery: PASS" FAIL_REGULAR_EXPRESSION "ui-test FAIL|ui_recovery: FAIL")
else()
  add_test(NAME ui_recovery COMMAND ${CMAKE_COMMAND} -E echo "ui_recovery skipped: xvfb-run not found (apt install xvfb)")
  set_tests_properties(ui_recovery PROPERTIES LABELS "ui" SKIP_REGULAR_EXPRESSION "skipped")
endif()
