# Soak test (issue 6): the editor under xvfb-run for a few thousand frames while a generated UI
# script changes lights, modes, cull mode, depth copy, window size (0x0 and back) and breaks then
# fixes a shader in a copy of shaders/; zero GL errors, stable GL object count and memory.
# About 3 minutes on two llvmpipe cores: labelled `soak` so quick runs can leave it out (-LE soak).
find_program(GBL_XVFB_RUN xvfb-run)
if(GBL_XVFB_RUN)
  add_test(NAME ui_soak
    COMMAND ${GBL_XVFB_RUN} -a -s "-screen 0 1280x720x24"
            sh ${CMAKE_CURRENT_SOURCE_DIR}/soak.sh $<TARGET_FILE:gbuffer-lab> ${CMAKE_SOURCE_DIR}/shaders
               ${CMAKE_CURRENT_BINARY_DIR}/soak)
  set_tests_properties(ui_soak PROPERTIES LABELS "ui;soak" TIMEOUT 900
    PASS_REGULAR_EXPRESSION "soak: PASS" FAIL_REGULAR_EXPRESSION "ui-test FAIL")
else()
  add_test(NAME ui_soak COMMAND ${CMAKE_COMMAND} -E echo "ui_soak skipped: xvfb-run not found (apt install xvfb)")
  set_tests_properties(ui_soak PROPERTIES LABELS "ui;soak" SKIP_REGULAR_EXPRESSION "skipped")
endif()
