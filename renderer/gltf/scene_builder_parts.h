// The glTF scene builder's state and steps, shared by scene_builder.cpp (the sequence and the node
// graph), scene_materials.cpp (images and materials), scene_meshes.cpp (primitives), scene_lights.cpp and
// scene_cameras.cpp.
#pragma once

#include "gltf/accessors.h"
#include "gltf/draco.h"
#include "gltf/scene_builder.h"

#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace gbl::gltf {

// Builds one SceneData from one model; used once, by buildScene().
class SceneBuilder {
public:
    SceneBuilder(tinygltf::Model const& model, Json const& doc, ImageStash& stash, GltfLoadOptions const& options,
                 Progress& progress)
        : model_(model), doc_(doc), stash_(stash), options_(options), progress_(progress), reader_(model, options) {}

    SceneData build();

private:
    // Validates the node graph (a forest: in-range children, one parent each, no cycles) and
    // returns the nodes of the chosen scene with their world matrices.
    std::vector<std::pair<int, glm::mat4>> placeNodes();

    // --- images and materials (scene_materials.cpp) ---------------------------------------
    int textureSource(int texture, std::string const& who);
    std::size_t countImages(std::set<int> const& materials);
    // The decoded image, or null (with a warning) when it is missing or unreadable.
    ImageData const* decoded(int image);
    // Index into scene_.images for a glTF image used as colour (sRGB) or as data (linear).
    int sceneImage(int image, bool srgb);
    int material(int index);
    void emissiveAndOcclusion(int index, Material& mat);

    // The coordinate set and KHR_texture_transform of one textureInfo object of material
    // `index`: materials[index].<parent>.<slot> (parent may be null). texCoord is tinygltf's.
    TextureTransform textureTransform(int index, char const* parent, char const* slot, int texCoord,
                                      std::string const& who);
    TextureTransform readTransform(Json const* textureInfo, int texCoord, std::string const& who);

    // --- meshes (scene_meshes.cpp) ----------------------------------------------------------
    std::vector<int> buildMesh(int meshIndex);
    Json const* dracoExtension(int meshIndex, std::size_t primitive, std::string const& who);
    // Null when the build cannot decode and the file has an uncompressed copy to use instead.
    std::optional<DracoPrimitive> decodeDraco(Json const& ext, tinygltf::Primitive const& prim, std::string const& who);

    // --- lights (scene_lights.cpp) ----------------------------------------------------------
    void addLights(std::vector<std::pair<int, glm::mat4>> const& placed);
    // The placed nodes' perspective cameras, into scene_.cameras (scene_cameras.cpp).
    void addCameras(std::vector<std::pair<int, glm::mat4>> const& placed, Bounds const& bounds);

    tinygltf::Model const& model_;
    Json const& doc_;
    ImageStash& stash_;
    GltfLoadOptions const& options_;
    Progress& progress_;
    ModelReader reader_;
    SceneData scene_;
    std::map<int, std::optional<ImageData>> decoded_;
    std::map<std::pair<int, bool>, int> sceneImages_;
    std::map<int, int> materials_;
    std::map<std::string, int> bakes_;
    std::size_t imagesToDecode_ = 1, imagesDecoded_ = 0;
    std::size_t uniqueTriangles_ = 0;
};

}  // namespace gbl::gltf
