# The course view of the Lessons window with real X clicks (issue 27): progress kept across a restart of the editor
# under Xvfb, checked through --log-frames. See ui_course.sh.
find_program(GBL_XVFB_RUN xvfb-run)
find_program(GBL_XDOTOOL xdotool)
if(GBL_XVFB_RUN AND GBL_XDOTOOL)
  add_test(NAME ui_course
    COMMAND ${GBL_XVFB_RUN} -a -s "-screen 0 1920x1080x24"
            sh ${CMAKE_CURRENT_SOURCE_DIR}/ui_course.sh $<TARGET_FILE:gbuffer-lab> ${CMAKE_CURRENT_BINARY_DIR}/ui_course)
  set_tests_properties(ui_course PROPERTIES LABELS "ui;gl" TIMEOUT 600
    PASS_REGULAR_EXPRESSION "ui_course: PASS" FAIL_REGULAR_EXPRESSION "ui_course: FAIL"
    SKIP_REGULAR_EXPRESSION "ui_course skipped")
else()
  add_test(NAME ui_course COMMAND ${CMAKE_COMMAND} -E echo
           "ui_course skipped: needs xvfb-run and xdotool (scripts/install-deps.sh installs both)")
  set_tests_properties(ui_course PROPERTIES LABELS "ui" SKIP_REGULAR_EXPRESSION "skipped")
endif()
