# Registers `format_check`: scripts/check-format.sh over the project's C++ files, so `ctest` alone covers formatting.
add_test(NAME format_check COMMAND bash ${CMAKE_SOURCE_DIR}/scripts/check-format.sh)
set_tests_properties(format_check PROPERTIES LABELS "cpu;format" TIMEOUT 120)
