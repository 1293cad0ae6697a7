// prepass mode (deferred lighting, docs/deferred_lighting.md): the thin G-buffer, the light pass
// into the diffuse and specular light targets, and the second geometry pass that applies the
// materials to them. The executor runs them in that order (core/frame_passes.h, prepassPasses).
#pragma once

#include "gl/fullscreen_triangle.h"
#include "gpu/draw_state_gl.h"
#include "gpu/gpu_scene.h"
#include "gpu/light_volume_gpu.h"
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
    gl::Framebuffer const& target;      // splitFbo (splitVolumeFbo with volumes): the light targets, cleared
    std::span<DrawState const> states;  // its declared draw groups: full screen, then any volumes'
};
// `prepass_lights: volumes`: after the full-screen draw (the directional lights alone, the declared
// group 0), each light's volume drawn with the cull mode (passes/light_volumes.h, drawLightVolumes,
// the declared groups after it), adding its diffuse and specular light.
struct PrepassLightVolumes {
    DeferredInputs deferred;  // the lights and shading uniforms; its depth is the thin pass's (sampled)
    LightVolumeGpu const& volumes;
    gl::Program const& program;      // ProgramId::PrepassLightVolume
    gl::Program const& stencilMark;  // ProgramId::LightVolumeStencil
    glm::mat4 viewProj{1.0f};
    CullMode cull = CullMode::Front;
};
// `volumes` null: the one full-screen draw sums every light.
void prepassLightPass(PrepassLightInput const& in, ShadingUniforms const& shading,
                      PrepassLightVolumes const* volumes = nullptr);

struct PrepassShadingInput {
    GpuScene const& scene;
    gl::Program const& program;  // ProgramId::PrepassShade
    gl::Texture const& diffuseLight;
    gl::Texture const& specularLight;
    LitTarget target;  // litFbo: the lit image (cleared) over the thin pass's depth
};
LightingOutput prepassShadingPass(PrepassShadingInput const& in, PrepassSceneConfig const& config);

}  // namespace gbl
