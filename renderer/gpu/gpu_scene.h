// The scene on the GPU: one vertex array per mesh, textures, materials and instances.
#pragma once

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
#include "gpu/draw_state_gl.h"
#include "scene/scene_data.h"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace gbl {

struct GpuMesh {
    gl::VertexArray vao;
    gl::Buffer vertices;
    gl::Buffer indices;
    GLsizei indexCount = 0;
    int material = -1;
    glm::vec3 center{0.0f};  // of its vertices' bounds, in the mesh's own space (the blended draws' sort key)
};

struct GpuScene {
    std::vector<gl::Texture> textures;  // one per SceneData image
    std::vector<Material> materials;
    std::vector<GpuMesh> meshes;
    std::vector<MeshInstance> instances;
    std::size_t triangleCount = 0;
    gl::Texture white;  // stands in for missing textures
};

// Uploads everything; returns an error (and leaves `out` untouched) when the scene is
// inconsistent (an index out of range, an image with the wrong byte count).
std::optional<std::string> uploadScene(SceneData const& scene, GpuScene& out);

// Which materials a draw includes.
enum class MaterialFilter { Opaque, Blended, All };

// Whether any instance has a blended material (the forward pass has something to draw).
bool hasBlended(GpuScene const& scene);

// Draws every instance whose material passes the filter with `program`, setting the per-object
// uniforms (uModel, uNormalMatrix) and material uniforms of shaders/material.glsl. The material
// textures go to the BIND_MATERIAL_* units of shaders/bindings.glsl. `states` are the pass's two
// declared draw groups (core/frame_passes.cpp, sceneStates): [0] for single-sided materials, [1]
// for double-sided ones; each is applied when the next draw's material needs it. `backToFrontFrom`: a
// view-projection to draw the instances in, farthest first by their centre's view depth
// (scene/draw_order.h), as blended surfaces need; without it they draw in list order.
void drawScene(GpuScene const& scene, gl::Program const& program, MaterialFilter filter, bool useNormalMaps,
               std::span<DrawState const> states, std::optional<glm::mat4> backToFrontFrom = std::nullopt);

}  // namespace gbl
