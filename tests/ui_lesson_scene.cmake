# A lesson on a glTF scene in the real editor: opening loads its scene, Leave the editor's again
# (xdotool clicks under Xvfb; skipped without the shared models). See ui_lesson_scene.sh.
gbl_xdotool_test(ui_lesson_scene)
set_tests_properties(ui_lesson_scene PROPERTIES ENVIRONMENT "GBL_SHARED_GLTF_DIR=${CMAKE_SOURCE_DIR}/../shared/gltf")
