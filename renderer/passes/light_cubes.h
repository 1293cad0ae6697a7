// Light cubes: one small emissive cube per light, an overlay drawn unlit onto the display image
// (after the view pass, tonemapped as the lit image is), depth-tested against the scene.
#pragma once

#include "gl/vertex_array.h"
#include "gpu/draw_state_gl.h"
#include "passes/shading_inputs.h"

#include <span>

namespace gbl {

struct LightCubesInput {
    LightBuffer const& lights;
    gl::Program const& program;   // ProgramId::LightCube
    gl::VertexArray const& cube;  // 36 vertices of a unit cube
    // RenderTargets::overlayFbo: the display image with the lit target's depth, which holds the
    // G-buffer's depth only when the depth-copy step ran (forward mode: its own depth).
    gl::Framebuffer const& target;
};
struct LightCubesConfig {
    glm::mat4 viewProj{1.0f};
    float halfSize = 0.05f;
    DisplayTonemap tonemap{};           // the display pass's, so a cube looks as it would in the lit image
    std::span<DrawState const> states;  // its declared draw groups (PassDecl::states), applied in order
};

void lightCubesPass(LightCubesInput const& in, LightCubesConfig const& config);

}  // namespace gbl
