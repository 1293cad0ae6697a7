// What the editor shows of an MSAA frame (docs/msaa.md, issue 47), as plain values: the complex
// pixels laid over the viewport, the samples-that-differ heat map, and each sample of one pixel.
#pragma once

#include "core/frame_types.h"
#include "core/gbuffer_layout.h"
#include "core/pipeline_settings.h"
#include "model/viewer_state.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gbl::ui {

// The viewport's MSAA views; offered while the frame shown ran msaa (samples > 0).
struct MsaaViewState {
    bool complexOverlay = false;  // the complex pixels tinted over the image
    bool samplesHeat = false;     // distinct samples per pixel on the heat scale, instead of the image
    // Set by the loop each frame: samples per pixel of the frame shown (0: it ran without msaa), its
    // complex pixels' share (the edges pass's count, else the heat map's) and the textures to draw.
    int samples = 0;
    std::optional<double> complexShare;
    unsigned overlayTexture = 0;
    unsigned heatTexture = 0;
    // Where the toolbar's checkboxes were drawn (x, y, w, h in window pixels), for the frame log.
    glm::vec4 complexRect{0.0f};
    glm::vec4 heatRect{0.0f};
};

// One sample of one pixel of the multisampled G-buffer, decoded as the lighting reads it
// (Renderer::readMsaaDecodedSample), whatever the layout.
struct MsaaPixelSample {
    glm::vec4 position{0.0f};  // w = 1 where drawn
    glm::vec4 normal{0.0f};    // unit, w = 1 where drawn
    glm::vec4 albedoSpec{0.0f};
    glm::vec4 emissiveAo{0.0f};
};

// Why each msaa choice (kMsaaNames order) cannot be picked here, empty where it can; the Pipeline
// window greys those out with the reason. `reason(samples)` is GlCaps::msaaUnavailableReason.
using MsaaReasons = std::array<std::string, kMsaaNames.size()>;
template <class Reason>  // std::string(int samples)
MsaaReasons msaaReasons(Reason reason) {
    MsaaReasons r;
    for (std::size_t i = 1; i < r.size(); ++i) r[i] = reason(msaaSamples(Msaa(i)));
    return r;
}

// The complex-pixel overlay: translucent magenta where `mask` (1 channel) is above 0.5, clear
// elsewhere; RGBA8 rows top to bottom.
std::vector<std::uint8_t> complexOverlayRgba(FloatImage const& mask);
// The complex pixels of a distinct-samples count image (Renderer::msaaDistinctSampleCounts): 1
// where two or more surfaces met, 1 channel.
FloatImage complexFromCounts(FloatImage const& counts);
// The share of mask pixels above 0.5 (0 for an empty mask).
double maskShare(FloatImage const& mask);
// The samples-that-differ heat map: each count's colour on the shared heat scale (core/heat_scale.h),
// opaque RGBA8 rows top to bottom.
std::vector<std::uint8_t> samplesHeatRgba(FloatImage const& counts);

// The multisampled G-buffer slot a viewer of `kind` shows one sample of; nullopt for the depth
// viewer and the lit frame, which have no sample read-back.
std::optional<GBufferSlot> viewerSampleSlot(ViewerKind kind);

// The selector's label of a sample choice: "all" for -1 (the resolved image), else "sample k".
std::string sampleChoiceLabel(int sample);
// A selected sample kept in range: -1 (all) when msaa is off or the sample is past the count.
int clampSample(int sample, int samples);

}  // namespace gbl::ui
