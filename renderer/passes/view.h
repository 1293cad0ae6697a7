// View pass: one frame image turned into displayable colour (shaders/view.frag): the tonemapped
// final image or a remapped debug view. The display pass and every texture viewer use it.
#pragma once

#include "core/pipeline_settings.h"
#include "core/view_params.h"
#include "gl/framebuffer.h"
#include "gl/fullscreen_triangle.h"
#include "gl/program.h"
#include "gpu/draw_state_gl.h"
#include "gpu/frame_resources.h"

#include <span>

namespace gbl {

struct ViewInput {
    GBufferTextures gbuffer;
    gl::Texture const& hdr;
    gl::Texture const& coverage;      // this frame's counts, for the heat map and tile views
    gl::Texture const& diffuseLight;  // accumulation split's targets, for their views
    gl::Texture const& specularLight;
    gl::Program const& program;  // ProgramId::View
    gl::FullscreenTriangle const& triangle;
    gl::Framebuffer const& target;  // RGBA8, frame-sized
    // prepass's thin G-buffer (docs/deferred_lighting.md), where the pass declares it (a prepass
    // frame): the G-buffer views show prepass.normal_exp and the lit depth in the layout's place.
    gl::Texture const* thinNormal = nullptr;
    gl::Texture const* thinDepth = nullptr;
};
struct ViewConfig {
    ViewParams params;
    Tonemap tonemap = Tonemap::Exposure;
    float exposure = 1.0f;
    float nearPlane = 0.1f;  // for the linear depth view
    float farPlane = 100.0f;
    int width = 0;
    int height = 0;
    glm::mat4 inverseViewProj{1.0f};    // decodes position in layouts that rebuild it from depth
    std::span<DrawState const> states;  // its declared draw groups (PassDecl::states), applied in order
};

void viewPass(ViewInput const& in, ViewConfig const& config);

}  // namespace gbl
