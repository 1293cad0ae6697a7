# The G-buffer layout combo with real X clicks (issue 12): the Pipeline window's combo opened and
# "packed" picked on the real editor under Xvfb; see ui_layout_combo.sh.
find_program(GBL_XVFB_RUN xvfb-run)
find_program(GBL_XDOTOOL xdotool)
if(GBL_XVFB_RUN AND GBL_XDOTOOL)
  add_test(NAME ui_layout_combo
    COMMAND ${GBL_XVFB_RUN} -a -s "-screen 0 1920x1080x24"
            sh ${CMAKE_CURRENT_SOURCE_DIR}/ui_layout_combo.sh $<TARGET_FILE:gbuffer-lab> ${CMAKE_CURRENT_BINARY_DIR}/ui_layout_combo)
  set_tests_properties(ui_layout_combo PROPERTIES LABELS "ui;gl" TIMEOUT 600
    PASS_REGULAR_EXPRESSION "ui_layout_combo: PASS" FAIL_REGULAR_EXPRESSION "ui_layout_combo: FAIL"
    SKIP_REGULAR_EXPRESSION "ui_layout_combo skipped")
else()
  add_test(NAME ui_layout_combo COMMAND ${CMAKE_COMMAND} -E echo
           "ui_layout_combo skipped: needs xvfb-run and xdotool (scripts/install-deps.sh installs both)")
  set_tests_properties(ui_layout_combo PROPERTIES LABELS "ui" SKIP_REGULAR_EXPRESSION "skipped")
endif()
