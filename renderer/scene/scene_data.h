// CPU-side scene: meshes, materials, images, instances and lights, before any GL upload.
// The procedural default scene and the glTF loader both produce this; the renderer uploads it.
#pragma once

#include "core/camera.h"
#include "core/point_light.h"
#include "scene/texture_transform.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gbl {

struct Vertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec2 uv{0.0f};
    glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};  // xyz tangent, w = bitangent sign
    glm::vec2 uv1{0.0f};                        // TEXCOORD_1 (zero where a mesh has none)
};

// 8-bit image, rows top to bottom. channels is 1..4.
struct ImageData {
    std::string name;
    int width = 0;
    int height = 0;
    int channels = 4;
    bool srgb = false;  // true for colour data (base colour); false for normals, specular
    std::vector<std::uint8_t> pixels;
};

enum class AlphaMode { Opaque, Mask, Blend };

struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};
    int baseColorTexture = -1;  // index into SceneData::images
    int normalTexture = -1;     // tangent-space normal map
    float normalScale = 1.0f;
    float specularFactor = 0.5f;     // specular intensity stored in the G-buffer's albedo alpha
    int specularTexture = -1;        // multiplies specularFactor; its red channel is used
    glm::vec3 emissiveFactor{0.0f};  // emitted radiance, linear; added after lighting (docs/lighting.md)
    int emissiveTexture = -1;        // sRGB colour, multiplies emissiveFactor
    int occlusionTexture = -1;       // red channel: ambient occlusion (1 = unoccluded)
    float occlusionStrength = 1.0f;  // ao = 1 + strength * (red - 1)
    // Coordinate set and KHR_texture_transform of each texture above.
    TextureTransform baseColorTransform;
    TextureTransform normalTransform;
    TextureTransform specularTransform;
    TextureTransform emissiveTransform;
    TextureTransform occlusionTransform;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
};

struct MeshData {
    std::string name;
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;  // triangle list
    int material = -1;                   // index into SceneData::materials, -1 = default
};

struct MeshInstance {
    int mesh = 0;
    glm::mat4 model{1.0f};
};

// A camera the file defines (glTF cameras), offered as a view. The renderer draws with the
// viewport's aspect; the file's aspect ratio is kept for information (0 = not given).
struct SceneCamera {
    std::string name;
    Camera camera;
    float aspectRatio = 0.0f;
};

struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    glm::vec3 center() const { return (min + max) * 0.5f; }
    float radius() const { return glm::length(max - min) * 0.5f; }
};

struct SceneData {
    std::string source;  // "default" or the file path
    std::vector<ImageData> images;
    std::vector<Material> materials;
    std::vector<MeshData> meshes;
    std::vector<MeshInstance> instances;
    std::vector<PointLight> lights;
    std::optional<Camera> camera;      // a suggested camera framing the scene
    std::vector<SceneCamera> cameras;  // the file's own cameras, in file order of the nodes using them
    std::vector<std::string> warnings;

    std::size_t triangleCount() const;
    Bounds bounds() const;  // world-space bounds over all instances
};

}  // namespace gbl
