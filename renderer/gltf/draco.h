// KHR_draco_mesh_compression for the glTF loader: decodes one compressed primitive when the build has Draco.
#pragma once

#include "gltf/loader.h"

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace gbl::gltf {

// A decoded primitive: per glTF attribute name, vertexCount * components values (as
// ModelReader::read returns them), and the triangle list's indices.
struct DracoPrimitive {
    std::size_t vertexCount = 0;
    std::map<std::string, std::vector<double>> attributes;
    std::vector<std::uint32_t> indices;
};

// Decodes `bytes` (the extension's buffer view). `attributeIds` maps glTF attribute names to
// the Draco attribute ids the extension lists; `components` gives the element size each name
// must have. Throws LoadFailure naming `who`; without Draco in the build it always fails with
// a sentence naming the missing library.
DracoPrimitive decodeDracoPrimitive(std::span<std::uint8_t const> bytes, std::map<std::string, int> const& attributeIds,
                                    std::map<std::string, int> const& components, std::string const& who,
                                    GltfLoadOptions const& options);

// The sentence that ends a refusal of Draco data in a build without the decoder.
inline constexpr char const* kNoDracoReason =
    "this build has no Draco decoder (configure it with the Draco library, Debian package libdraco-dev)";

}  // namespace gbl::gltf
