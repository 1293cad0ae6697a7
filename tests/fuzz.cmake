# Registers `gltf_fuzz`: a separate clang + libFuzzer build of the glTF loader, fuzzed for 30 s.
add_test(NAME gltf_fuzz
  COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/run_fuzz.sh ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/gltf-fuzz 30)
# The sanitizer build of the loader takes a few minutes on two cores before the 30 s of fuzzing.
set_tests_properties(gltf_fuzz PROPERTIES LABELS fuzz TIMEOUT 1200)
