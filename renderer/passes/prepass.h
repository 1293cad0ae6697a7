// prepass mode (deferred lighting, docs/deferred_lighting.md): the thin G-buffer, the light pass
// into the diffuse and specular light targets, and the second geometry pass that applies the
// materials to them. The executor runs them in that order (core/frame_passes.h, prepassPasses).
#pragma once

#include "gl/fullscreen_triangle.h"
#include "gpu/draw_state_gl.h"
#include "gpu/gpu_scene.h"
#include "passes/shading_inputs.h"

#include <glm/glm.hpp>

#include <span>

namespace gbl {

struct PrepassGeometryInput {
    GpuScene const& scene;
    gl::Program const& program;     // ProgramId::PrepassGeometry
    gl::Framebuffer const& target;  // prepassFbo: the normal/exponent target and the lit depth, cleared
};
struct PrepassSceneConfig {
    glm::mat4 viewProj{1.0f};
    ShadingUniforms shading;  // the exponent (geometry), the ambient term (shading)
    bool normalMaps = true;
    std::span<DrawState const> states;  // declared: single-sided, double-sided materials (drawScene)
};
void prepassGeometryPass(PrepassGeometryInput const& in, PrepassSceneConfig const& config);

struct PrepassLightInput {
    gl::Texture const& normalExponent;  // the thin G-buffer's colour target
    gl::Texture const& depth;           // its depth: the lit target's
    LightBuffer const& lights;
    gl::Program const& program;  // ProgramId::PrepassLight
    gl::FullscreenTriangle const& triangle;
    gl::Framebuffer const& target;      // splitFbo: the diffuse and specular light targets, cleared
    std::span<DrawState const> states;  // its one declared draw group
};
void prepassLightPass(PrepassLightInput const& in, ShadingUniforms const& shading);

struct PrepassShadingInput {
    GpuScene const& scene;
    gl::Program const& program;  // ProgramId::PrepassShade
    gl::Texture const& diffuseLight;
    gl::Texture const& specularLight;
    LitTarget target;  // litFbo: the lit image (cleared) over the thin pass's depth
};
LightingOutput prepassShadingPass(PrepassShadingInput const& in, PrepassSceneConfig const& config);

}  // namespace gbl
