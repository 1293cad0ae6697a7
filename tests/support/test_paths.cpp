// Paths to test data, the shared glTF models and the built executable.
#include "test_paths.h"

#include <filesystem>

namespace gbl::test {
std::string dataDir() {
    return GBL_TEST_DATA_DIR;
}
std::string sharedGltfDir() {
    return GBL_SHARED_GLTF_DIR;
}
std::string binaryPath() {
    return GBL_BINARY;
}
std::string sourcePath(std::string const& relative) {
    return (std::filesystem::path(GBL_SOURCE_DIR) / relative).string();
}
}  // namespace gbl::test
