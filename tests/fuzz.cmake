# Registers `gltf_fuzz` and `manifest_fuzz`: a separate clang + libFuzzer build of the glTF loader and
# of the G-buffer manifest reader (issue 28), fuzzed for 20 s and 10 s. The first builds both targets;
# the second waits for it (one build folder) and fuzzes the manifest reader.
add_test(NAME gltf_fuzz
  COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/run_fuzz.sh ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/gltf-fuzz 20 gltf_fuzz)
# The sanitizer build of the libraries takes a few minutes on two cores before the fuzzing.
set_tests_properties(gltf_fuzz PROPERTIES LABELS fuzz TIMEOUT 1200 RESOURCE_LOCK fuzz_build)
add_test(NAME manifest_fuzz
  COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/run_fuzz.sh ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/gltf-fuzz 10 manifest_fuzz)
set_tests_properties(manifest_fuzz PROPERTIES LABELS fuzz TIMEOUT 1200 RESOURCE_LOCK fuzz_build DEPENDS gltf_fuzz)
