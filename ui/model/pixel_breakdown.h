// The pixel inspector's per-light breakdown, computed from a pixel sample with the CPU copy of
// the lighting shader (renderer/shading_cpu.h), so its sum is the lit value the GPU stored.
#pragma once

#include "core/camera.h"
#include "core/pipeline_settings.h"
#include "model/pixel_inspector_state.h"

#include <span>

namespace gbl::ui {

// Where the sampled pixel is in the frame: what the "why this value" verdicts need.
struct PixelInFrame {
    glm::ivec2 pixel{0};  // top-left origin
    glm::ivec2 frameSize{0};
    std::optional<TileDepthBounds> tileBounds;  // tiled mode: the tile's depth bounds
};

// nullopt for background pixels (nothing to light). With `where`, verdicts holds one entry per
// light (explainPixel); without it, verdicts stays empty.
std::optional<PixelBreakdown> breakDownPixel(PixelSample const& sample, std::span<PointLight const> lights,
                                             Camera const& camera, PipelineSettings const& settings,
                                             std::optional<PixelInFrame> const& where = std::nullopt);

}  // namespace gbl::ui
