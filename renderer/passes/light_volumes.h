// Light volumes: one enclosing sphere per light, drawn instanced and added by blending, with
// the five cull modes (back, front, none, flip, stencil). Shared by the volumes lighting pass,
// its coverage counts and the wireframes.
#pragma once

#include "core/camera.h"
#include "core/pipeline_settings.h"
#include "core/point_light.h"
#include "gl/fullscreen_triangle.h"
#include "gpu/draw_state_gl.h"
#include "gpu/light_volume_gpu.h"
#include "passes/shading_inputs.h"

#include <span>

namespace gbl {

// Which list a light's volume goes in this frame: its mesh (core/light_volume_cone.h's
// volumeShape) and whether the camera's near plane may cut into that very mesh.
enum class VolumeGroup { None, SphereOutside, SphereInside, ConeOutside, ConeInside };
struct VolumeGrouping {
    glm::vec3 eye{0.0f};
    float nearCorner = 0.0f;       // nearPlaneCornerDistance of the camera
    float sphereScale = 1.0f;      // LightVolumeGpu::enclosingScale
    float coneRadialScale = 1.0f;  // LightVolumeGpu::coneRadialScale
    float volumeScale = 1.0f;      // LightVolumeGpu::volumeScale
};
VolumeGroup volumeGroup(PointLight const& light, VolumeGrouping const& g);

// Fills volumes.instances with this frame's lights (radius > 0): sphere lights, then cone lights,
// each with the ones whose volume may hold the camera last, so `flip` draws contiguous ranges.
struct VolumeInstancesConfig {
    Camera camera;
    float aspect = 1.0f;
    std::span<PointLight const> lights;
};
void prepareVolumeInstances(LightVolumeGpu& volumes, VolumeInstancesConfig const& config);

// Draws the volumes with `program` added (blend ONE, ONE) into the bound framebuffer, each group of
// draws with its state from `groups` (the volume states core/frame_passes.cpp declares for `cull`);
// `stencilMark` is the marking program of the stencil mode.
struct LightVolumeDraw {
    DeferredInputs deferred;
    LightVolumeGpu const& volumes;
    gl::Program const& program;
    gl::Program const& stencilMark;  // ProgramId::LightVolumeStencil
};
void drawLightVolumes(LightVolumeDraw const& in, glm::mat4 const& viewProj, CullMode cull,
                      std::span<DrawState const> groups);

struct LightingVolumesInput {
    DeferredInputs deferred;
    LightVolumeGpu const& volumes;   // instances prepared for this frame
    gl::Program const& ambient;      // ProgramId::LightingQuad, run with no lights
    gl::Program const& shade;        // ProgramId::LightVolume
    gl::Program const& stencilMark;  // ProgramId::LightVolumeStencil
    gl::FullscreenTriangle const& triangle;
    LitTarget target;  // volumeFbo: the HDR image and RenderTargets::volumeDepthStencil()
};
struct LightingVolumesConfig {
    glm::mat4 viewProj{1.0f};
    CullMode cull = CullMode::Front;
    std::span<DrawState const> states;  // its declared draw groups (PassDecl::states), applied in order
};

// Ambient full-screen, then the volumes added by blending. Cost: one full-screen pass plus the
// pixels each light's volume covers, not pixels x lights.
LightingOutput lightingVolumesPass(LightingVolumesInput const& in, LightingVolumesConfig const& config);

}  // namespace gbl
