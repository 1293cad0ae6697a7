// The glTF loader's scene builder: turns a parsed, pre-checked model into a CPU SceneData.
#pragma once

#include "gltf/failure.h"
#include "gltf/precheck.h"
#include "scene/scene_data.h"

#include <tiny_gltf.h>

#include <cstdint>
#include <map>
#include <vector>

namespace gbl::gltf {

// Encoded image bytes from external files and data: URIs, kept by image index: decoding happens
// in the builder, once every byte range has been checked, with progress reported per image.
struct ImageStash {
    std::map<int, std::vector<std::uint8_t>> encoded;
};

// Validates the node graph, every index and accessor range, then builds meshes, materials
// (decoding the images they use), lights and a framing camera. Throws LoadFailure or
// LoadCancelled; `doc` is the same file's JSON for the extensions tinygltf does not model.
SceneData buildScene(tinygltf::Model const& model, Json const& doc, ImageStash& stash, GltfLoadOptions const& options,
                     Progress& progress);

}  // namespace gbl::gltf
