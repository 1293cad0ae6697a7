# Sessions in the editor (issue 6): save, undo/redo, reopen, bad files and exports through the
# real editor under xvfb-run; `--session FILE` for the editor, with a good and a bad file.
find_program(GBL_XVFB_RUN xvfb-run)
set(GBL_SESSION_DATA ${CMAKE_CURRENT_SOURCE_DIR}/data/sessions)
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/ui_session_out)
configure_file(${CMAKE_CURRENT_SOURCE_DIR}/ui_session_script.txt.in ${CMAKE_CURRENT_BINARY_DIR}/ui_session_script.txt @ONLY)
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/ui_session_open_script.txt
  "frames 3\nexpect-lights 3\nexpect-setting mode volumes\nexpect-setting cull back\nexpect-light 1 kq 0.5\nexpect-no-gl-errors\n")
if(GBL_XVFB_RUN)
  set(xvfb ${GBL_XVFB_RUN} -a -s "-screen 0 1280x720x24")
  add_test(NAME ui_session
    COMMAND ${xvfb} $<TARGET_FILE:gbuffer-lab> --ui-test ${CMAKE_CURRENT_BINARY_DIR}/ui_session_script.txt
            --size 800x500 --no-vsync
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  add_test(NAME ui_session_option
    COMMAND ${xvfb} $<TARGET_FILE:gbuffer-lab> --session ${GBL_SESSION_DATA}/three_lights.json
            --ui-test ${CMAKE_CURRENT_BINARY_DIR}/ui_session_open_script.txt --size 640x400 --no-vsync)
  # A bad session file: one sentence naming the field, exit code 2 (checked by WILL_FAIL + the message).
  add_test(NAME ui_session_option_bad
    COMMAND ${xvfb} $<TARGET_FILE:gbuffer-lab> --session ${GBL_SESSION_DATA}/bad_kq.json --frames 3 --size 320x200)
  set_tests_properties(ui_session ui_session_option PROPERTIES LABELS "ui;gl" TIMEOUT 600
    FAIL_REGULAR_EXPRESSION "ui-test FAIL")
  set_tests_properties(ui_session_option_bad PROPERTIES LABELS "ui;gl" TIMEOUT 300
    PASS_REGULAR_EXPRESSION "bad_kq.json: lights\\[0\\]\\.kq must be a finite number >= 0")
else()
  add_test(NAME ui_session COMMAND ${CMAKE_COMMAND} -E echo "ui_session skipped: xvfb-run not found (apt install xvfb)")
  set_tests_properties(ui_session PROPERTIES LABELS "ui" SKIP_REGULAR_EXPRESSION "skipped")
endif()
