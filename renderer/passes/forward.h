// Forward shading: every light evaluated per fragment while drawing each object (no G-buffer).
// Opaque: the `forward` lighting mode. Blended: transparent materials after the deferred
// lighting, depth-tested against the scene and not writing depth.
#pragma once

#include "gpu/draw_state_gl.h"
#include "gpu/gpu_scene.h"
#include "passes/shading_inputs.h"
#include "passes/tile_bins.h"

#include <span>

namespace gbl {

struct ForwardInput {
    GpuScene const& scene;
    LightBuffer const& lights;
    gl::Program const& program;  // ProgramId::Forward
    LitTarget target;            // Opaque clears it first; Blended blends over it
    // forward+ (program ProgramId::ForwardPlus): the tiles' candidate lists, binned this frame
    // (Blended: TileBins::blendedCounts and blendedLights, binned from the near plane).
    TileBins const* tiles = nullptr;
};
struct ForwardConfig {
    MaterialFilter filter = MaterialFilter::Opaque;
    glm::mat4 viewProj{1.0f};
    ShadingUniforms shading;
    bool normalMaps = true;
    std::span<DrawState const> states;  // declared: single-sided, double-sided materials (drawScene)
    bool backToFront = false;           // drawn farthest object first (blended surfaces: the over operator)
    int tilesX = 0;                     // forward+: tiles per row of the binning grid
};

LightingOutput forwardPass(ForwardInput const& in, ForwardConfig const& config);

}  // namespace gbl
