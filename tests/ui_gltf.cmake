# Loading glTF scenes in the real editor under xvfb-run, driven by tests/ui_gltf_script.txt:
# File > Open on the worker thread, a broken file keeping the previous scene, a cancelled load
# (held at a stage so the cancel is deterministic), lights from the file, drag-and-drop. Skips
# with a message when the shared models (../shared/gltf) are absent. Writes ui_gltf_helmet.png.
find_program(GBL_XVFB_RUN xvfb-run)
if(GBL_XVFB_RUN)
  add_test(NAME ui_gltf
    COMMAND ${GBL_XVFB_RUN} -a -s "-screen 0 1920x1080x24"
            $<TARGET_FILE:gbuffer-lab> --ui-test ${CMAKE_CURRENT_SOURCE_DIR}/ui_gltf_script.txt
            --size 1280x720 --no-vsync
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(ui_gltf PROPERTIES LABELS "ui;gl" TIMEOUT 900
    ENVIRONMENT "GBL_SHARED_GLTF_DIR=${CMAKE_SOURCE_DIR}/../shared/gltf;GBL_TEST_DATA_DIR=${CMAKE_CURRENT_SOURCE_DIR}/data"
    FAIL_REGULAR_EXPRESSION "ui-test FAIL"
    SKIP_REGULAR_EXPRESSION "ui-test SKIP")
else()
  add_test(NAME ui_gltf COMMAND ${CMAKE_COMMAND} -E echo "ui_gltf skipped: xvfb-run not found (apt install xvfb)")
  set_tests_properties(ui_gltf PROPERTIES LABELS "ui" SKIP_REGULAR_EXPRESSION "skipped")
endif()
