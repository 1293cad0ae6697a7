# The Lessons window with real X clicks (issue 10): Start, Next, Back and Leave on the real editor
# under Xvfb, checked through --log-frames, and screenshots of a lesson step. See ui_lessons.sh.
find_program(GBL_XVFB_RUN xvfb-run)
find_program(GBL_XDOTOOL xdotool)
if(GBL_XVFB_RUN AND GBL_XDOTOOL)
  add_test(NAME ui_lessons
    COMMAND ${GBL_XVFB_RUN} -a -s "-screen 0 1920x1080x24"
            sh ${CMAKE_CURRENT_SOURCE_DIR}/ui_lessons.sh $<TARGET_FILE:gbuffer-lab> ${CMAKE_CURRENT_BINARY_DIR}/ui_lessons)
  set_tests_properties(ui_lessons PROPERTIES LABELS "ui;gl" TIMEOUT 600
    PASS_REGULAR_EXPRESSION "ui_lessons: PASS" FAIL_REGULAR_EXPRESSION "ui_lessons: FAIL"
    SKIP_REGULAR_EXPRESSION "ui_lessons skipped")
else()
  add_test(NAME ui_lessons COMMAND ${CMAKE_COMMAND} -E echo
           "ui_lessons skipped: needs xvfb-run and xdotool (scripts/install-deps.sh installs both)")
  set_tests_properties(ui_lessons PROPERTIES LABELS "ui" SKIP_REGULAR_EXPRESSION "skipped")
endif()
