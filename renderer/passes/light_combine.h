// The combine pass of `accumulation: split`: ambient and emission from the G-buffer plus the two
// accumulation targets, albedo * diffuse + specular, into the HDR lit image (docs/lighting.md).
#pragma once

#include "gl/fullscreen_triangle.h"
#include "gpu/draw_state_gl.h"
#include "passes/shading_inputs.h"

#include <span>

namespace gbl {

struct LightCombineInput {
    GBufferTextures gbuffer;
    ShadingUniforms shading;           // ambient, emissive weight, inverse view-projection
    gl::Texture const& diffuseLight;   // RGBA16F: sum of N.L * attenuation * colour
    gl::Texture const& specularLight;  // RGBA16F: sum of specular * (N.H)^shininess * attenuation * colour
    gl::Program const& program;        // ProgramId::LightCombine
    gl::FullscreenTriangle const& triangle;
    LitTarget target;                   // every pixel of the HDR image is written (0 on the background)
    std::span<DrawState const> states;  // its declared draw groups (PassDecl::states), applied in order
};

LightingOutput lightCombinePass(LightCombineInput const& in);

}  // namespace gbl
