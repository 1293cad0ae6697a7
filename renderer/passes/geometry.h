// Geometry pass: the opaque scene into the G-buffer.
#pragma once

#include "gl/program.h"
#include "gpu/draw_state_gl.h"
#include "gpu/gpu_scene.h"
#include "gpu/render_targets.h"

#include <glm/glm.hpp>

#include <span>

namespace gbl {

struct GeometryInput {
    GpuScene const& scene;
    gl::Program const& program;  // ProgramId::Geometry
    GBuffer const& target;       // cleared, then written
};
struct GeometryConfig {
    glm::mat4 viewProj{1.0f};
    bool normalMaps = true;
    std::span<DrawState const> states;  // its declared draw groups (PassDecl::states), applied in order
};
struct GeometryOutput {
    GBuffer const& gbuffer;  // position, normal, albedo/specular and depth of the opaque scene
};

GeometryOutput geometryPass(GeometryInput const& in, GeometryConfig const& config);

// forward+'s depth pre-pass: the same draws into `depthTarget` (the lit target), whose declared
// state writes depth and no colour.
void depthPrepass(GeometryInput const& in, GeometryConfig const& config, gl::Framebuffer const& depthTarget);

}  // namespace gbl
