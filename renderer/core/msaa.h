// The MSAA G-buffer's rules as plain values (docs/msaa.md): which frames can light a multisampled
// G-buffer, and the thresholds that make a pixel complex (its samples lit one by one).
#pragma once

#include "core/gbuffer_layout.h"
#include "core/pipeline_settings.h"

#include <optional>
#include <string>

namespace gbl {

// When the samples of a pixel differ enough for the edges strategy to light each one
// (shaders/msaa_edges.frag compares every sample with sample 0). Background against geometry is
// always complex.
struct MsaaThresholds {
    // A position further from sample 0's tangent plane (its position and normal) than this share of
    // the distance from the eye to sample 0.
    float relativeDistance = 0.01f;
    // Normals whose cosine is below this (about 8 degrees apart).
    float normalCos = 0.99f;
    // Albedo or specular that differs by more than this in any channel (of 1).
    float albedo = 0.05f;
};
inline constexpr MsaaThresholds kMsaaThresholds{};

// Why the frame of `s` (its mode after any fallback) cannot light a multisampled G-buffer, in one
// sentence that says what ran instead, or nullopt when it can (or msaa is off). `imported`: the frame
// re-lights an imported G-buffer, which has one sample per pixel. Every layout has its multisampled
// G-buffer; the quad pass and the light volumes read its samples. The compute modes (tiled,
// clustered) shade one texel per pixel, and forward and forward+ draw no G-buffer: they refuse.
inline std::optional<std::string> msaaFrameRefusal(PipelineSettings const& s, bool imported) {
    if (s.msaa == Msaa::Off) return std::nullopt;
    std::string const n = std::string(kMsaaNames[std::size_t(s.msaa)]);
    auto const refuse = [&](std::string const& why) { return "msaa " + n + " " + why + ", so msaa was off"; };
    if (imported) return refuse("needs a G-buffer drawn here and an imported one has one sample per pixel");
    if (s.mode != LightingMode::Quad && s.mode != LightingMode::Volumes)
        return refuse("is lit by the quad and volumes passes only and this frame ran " +
                      std::string(kLightingModeNames[std::size_t(s.mode)]) + " mode");
    if (s.accumulation != LightAccumulation::Single) return refuse("lights into one target, not split ones");
    return std::nullopt;
}

// The cull mode whose faces the volumes draw over complex pixels (msaa volumes, no depth test there:
// core/frame_passes_msaa.cpp). The stencil mode's mark counts depth failures, so it cannot run
// without the depth test: its volumes draw their back faces alone, as front's do.
constexpr CullMode msaaComplexCull(CullMode cull) {
    return cull == CullMode::Stencil ? CullMode::Front : cull;
}

// --- memory (docs/msaa.md) -----------------------------------------------------------------------

// Bytes the multisampled targets of an msaa frame take at width x height: the layout's attachments
// `samples` times. Every lighting mode lights into the single-sample lit image.
inline double msaaTargetBytes(GBufferLayoutDesc const& d, int samples, int width, int height) {
    return double(layoutBytesPerPixel(d)) * double(samples) * double(width) * double(height);
}

// The multisampled targets' memory at each sample count, one line for the Stats window and bench:
// "msaa targets at 1280x720: 2x 66.4 MB, 4x ...".
inline std::string msaaMemoryLine(GBufferLayoutDesc const& d, int width, int height) {
    std::string out = "msaa targets at " + std::to_string(width) + "x" + std::to_string(height) + ":";
    auto const mb = [](double bytes) {
        std::string s = std::to_string(static_cast<long long>(bytes / 1.0e5 + 0.5));  // tenths of a MB
        if (s.size() < 2) s.insert(0, "0");
        return s.substr(0, s.size() - 1) + "." + s.substr(s.size() - 1) + " MB";
    };
    for (int n : {2, 4, 8})
        out += std::string(n == 2 ? " " : ", ") + std::to_string(n) + "x " + mb(msaaTargetBytes(d, n, width, height));
    return out;
}

// Without a driver that reports its free memory, msaa targets may take up to this many bytes.
inline constexpr double kMsaaFixedBudgetBytes = 1024.0 * 1024.0 * 1024.0;

// Megabytes (10^6 bytes) as the refusal writes them.
inline std::string msaaMegabytes(double bytes) {
    return std::to_string(static_cast<long long>(bytes / 1.0e6 + 0.5)) + " MB";
}

// Why targets of `bytes` exceed `budgetBytes` (its source said in `budgetSource`), or nullopt.
inline std::optional<std::string> msaaBudgetRefusal(Msaa msaa, double bytes, double budgetBytes,
                                                    std::string const& budgetSource, int width, int height) {
    if (bytes <= budgetBytes) return std::nullopt;
    return "msaa " + std::string(kMsaaNames[std::size_t(msaa)]) + " needs " + msaaMegabytes(bytes) +
           " for its multisampled targets at " + std::to_string(width) + "x" + std::to_string(height) +
           " and the budget is " + msaaMegabytes(budgetBytes) + " (" + budgetSource + "), so msaa was off";
}

}  // namespace gbl
