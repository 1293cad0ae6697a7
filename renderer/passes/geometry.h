// Geometry pass: the opaque scene into the G-buffer.
#pragma once

#include "gl/framebuffer.h"
#include "gl/program.h"
#include "gpu/draw_state_gl.h"
#include "gpu/gpu_scene.h"

#include <glm/glm.hpp>

#include <span>

namespace gbl {

struct GeometryInput {
    GpuScene const& scene;
    gl::Program const& program;     // ProgramId::Geometry
    gl::Framebuffer const& target;  // the G-buffer's: cleared by the executor, then written
};
struct GeometryConfig {
    glm::mat4 viewProj{1.0f};
    bool normalMaps = true;
    std::span<DrawState const> states;  // declared: single-sided, double-sided materials (drawScene)
};
struct GeometryOutput {
    gl::Framebuffer const& gbuffer;  // position, normal, albedo/specular and depth of the opaque scene
};

GeometryOutput geometryPass(GeometryInput const& in, GeometryConfig const& config);

// forward+'s depth pre-pass is this pass into the lit target's framebuffer, under a declared state
// that writes depth and no colour (core/frame_passes.cpp).

}  // namespace gbl
