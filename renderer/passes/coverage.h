// Coverage counts behind the heat map and the lights-per-tile view: x = lights whose shading ran
// at the pixel (volume fragments, tile-list entries, or every light for quad), y = lights that
// actually reached the surface there.
#pragma once

#include "core/frame_passes.h"
#include "gl/fullscreen_triangle.h"
#include "gpu/draw_state_gl.h"
#include "passes/light_volumes.h"
#include "passes/lighting_tiled.h"

#include <span>

namespace gbl {

struct CoverageInput {
    DeferredInputs deferred;
    gl::FullscreenTriangle const& triangle;
    gl::Program const& allLights;  // ProgramId::CoverageAllLights
    // Null where the mode's programs are unavailable: those counts then stay zero.
    LightVolumeGpu const* volumes;      // instances prepared for this frame
    gl::Program const* volumeCoverage;  // ProgramId::LightVolumeCoverage
    gl::Program const* volumeStencil;   // ProgramId::LightVolumeStencil
    gl::Program const* tiled;           // ProgramId::LightingTiled
    TileBinPrograms const* tiledBin;    // ProgramId::TileDepth and TileBin (with `tiled`)
    TileBins* bins;                     // (with `tiled`)
    gl::Framebuffer const& target;      // coverageFbo: the counts and volumeDepthStencil()
    gl::Texture const& coverage;        // its colour attachment (the tiled pass writes it as an image)
    gl::Texture const& hdr;             // bound (not written) as the tiled program's lit and specular images
    GlCaps const& caps;                 // the tiled lists' storage limit
};
struct CoverageConfig {
    LightingMode mode = LightingMode::Quad;
    CullMode cull = CullMode::Front;
    DebugView view = DebugView::Heatmap;
    LightingTiledConfig tiled;  // matrices and size; shade/coverage are set by the pass
    glm::mat4 viewProj{1.0f};
    std::span<DrawState const> states;  // its declared draw groups (PassDecl::states), applied in order
};
struct CoverageOutput {
    gl::Texture const& coverage;
};

// The lights-per-tile view always shows the tiled mode's lists (when compute exists). Forward
// mode has no G-buffer to count over: the counts stay zero.
CoverageOutput coveragePass(CoverageInput const& in, CoverageConfig const& config);

}  // namespace gbl
