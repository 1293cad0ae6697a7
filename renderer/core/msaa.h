// The MSAA G-buffer's rules as plain values (docs/msaa.md): which frames can light a multisampled
// G-buffer, and the thresholds that make a pixel complex (its samples lit one by one).
#pragma once

#include "core/pipeline_settings.h"

#include <optional>
#include <string>

namespace gbl {

// When the samples of a pixel differ enough for the edges strategy to light each one
// (shaders/msaa_edges.frag compares every sample with sample 0). Background against geometry is
// always complex.
struct MsaaThresholds {
    // Positions further apart than this share of the distance from the eye to sample 0.
    float relativeDistance = 0.01f;
    // Normals whose cosine is below this (about 8 degrees apart).
    float normalCos = 0.99f;
    // Albedo or specular that differs by more than this in any channel (of 1).
    float albedo = 0.05f;
};
inline constexpr MsaaThresholds kMsaaThresholds{};

// Why the frame of `s` (its mode after any fallback) cannot light a multisampled G-buffer, in one
// sentence that says what ran instead, or nullopt when it can (or msaa is off). `imported`: the frame
// re-lights an imported G-buffer, which has one sample per pixel.
inline std::optional<std::string> msaaFrameRefusal(PipelineSettings const& s, bool imported) {
    if (s.msaa == Msaa::Off) return std::nullopt;
    std::string const n = std::string(kMsaaNames[std::size_t(s.msaa)]);
    auto const refuse = [&](std::string const& why) { return "msaa " + n + " " + why + ", so msaa was off"; };
    if (imported) return refuse("needs a G-buffer drawn here and an imported one has one sample per pixel");
    if (s.mode != LightingMode::Quad)
        return refuse("is lit by the quad pass only and this frame ran " +
                      std::string(kLightingModeNames[std::size_t(s.mode)]) + " mode");
    if (s.layout != GBufferLayout::Classic)
        return refuse("has its multisampled G-buffer in the classic layout only and this frame used " +
                      std::string(kGBufferLayoutNames[std::size_t(s.layout)]));
    if (s.accumulation != LightAccumulation::Single) return refuse("lights into one target, not split ones");
    return std::nullopt;
}

}  // namespace gbl
