// The pixel inspector's per-light breakdown, computed from a pixel sample with the CPU copy of
// the lighting shader (renderer/shading_cpu.h), so its sum is the lit value the GPU stored.
#pragma once

#include "core/camera.h"
#include "core/pipeline_settings.h"
#include "model/pixel_inspector_state.h"

#include <span>
#include <string>

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

// The inspector's flag: the stored lit value against ambient plus every light on the CPU (the
// sum of docs/lighting.md). They agree within the fp16 bound the GL tests use for one stored
// value, 2e-3 x max(1, |sum|) per channel (2^-11 storage plus GPU-vs-CPU pow()).
struct ValueCheck {
    bool agrees = true;
    float error = 0.0f;    // largest |stored - sum| over RGB
    float allowed = 0.0f;  // the bound at that channel
    std::string cause;     // the likely cause, one sentence, when they disagree
};
inline float storedValueBound(float sum) {
    return 2e-3f * std::max(1.0f, std::abs(sum));
}
ValueCheck checkStoredValue(glm::vec3 stored, PixelBreakdown const& breakdown, PipelineSettings const& settings);

// What the inspector says where there is no breakdown: background, or forward mode, which has no
// G-buffer for the CPU to read (its lit value is still stored).
std::string noBreakdownNote(PixelSample const& sample, PipelineSettings const& settings);

}  // namespace gbl::ui
