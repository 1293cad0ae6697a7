# The editor's UI test: the real editor under xvfb-run, driven by tests/ui_editor_script.txt.
# It checks every window is visible, that cull mode and depth copy change the frame, validated
# light edits, light picking and resizing, then writes ui_editor.png in the build's tests folder.
find_program(GBL_XVFB_RUN xvfb-run)
if(GBL_XVFB_RUN)
  add_test(NAME ui_editor
    COMMAND ${GBL_XVFB_RUN} -a -s "-screen 0 1920x1080x24"
            $<TARGET_FILE:gbuffer-lab> --ui-test ${CMAKE_CURRENT_SOURCE_DIR}/ui_editor_script.txt
            --size 1280x720 --no-vsync
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(ui_editor PROPERTIES LABELS "ui;gl" TIMEOUT 900
    FAIL_REGULAR_EXPRESSION "ui-test FAIL")
else()
  # Registered anyway so the suite says why it did not run instead of silently omitting it.
  add_test(NAME ui_editor COMMAND ${CMAKE_COMMAND} -E echo "ui_editor skipped: xvfb-run not found (apt install xvfb)")
  set_tests_properties(ui_editor PROPERTIES LABELS "ui" SKIP_REGULAR_EXPRESSION "skipped")
endif()
