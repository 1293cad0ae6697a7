// Where the tests find their inputs and the program under test.
#pragma once

#include <string>

namespace gbl::test {
std::string dataDir();                                // tests/data in the source tree
std::string sharedGltfDir();                          // ../shared/gltf beside the project (may be absent)
std::string binaryPath();                             // the built gbuffer-lab executable
std::string sourcePath(std::string const& relative);  // a file or folder of the source tree
}  // namespace gbl::test
