// The one colour scale of every count heat map (issue 13): volumes per pixel, lights per tile and
// lights per cluster. Counts fall in logarithmic bins 0, 1, 2-3, 4-7, 8-15, 16-31, 32-63, 64+, each
// with one flat colour, so a count can be read off the colour. shaders/view.frag (heatBin,
// heatLegend) is the twin; HEAT_* in shaders/view_constants.glsl hold the same numbers
// (shader_constants_test checks them).
#pragma once

#include "core/pipeline_settings.h"

#include <glm/glm.hpp>

#include <array>
#include <string>
#include <string_view>

namespace gbl {

inline constexpr int kHeatBins = 8;
// Bin k holds the counts from kHeatBinEdges[k] up to (not including) kHeatBinEdges[k + 1]; the
// last bin has no upper end.
inline constexpr std::array<int, kHeatBins> kHeatBinEdges{0, 1, 2, 4, 8, 16, 32, 64};
// sRGB bytes per bin: black for nothing, then blue -> cyan -> green -> yellow -> orange -> red ->
// magenta, hues far enough apart that the heat map's dimmed pixels keep their hue.
inline constexpr std::array<std::array<int, 3>, kHeatBins> kHeatBinColors{{{0, 0, 0},
                                                                           {40, 60, 220},
                                                                           {0, 160, 255},
                                                                           {0, 200, 140},
                                                                           {120, 220, 30},
                                                                           {250, 220, 0},
                                                                           {255, 120, 0},
                                                                           {230, 0, 180}}};
// The heat map (DebugView::Heatmap) scales a pixel's colour by mix(this, 1, lit / evaluated): dim
// where the lights evaluated there did not light the surface (wasted work).
inline constexpr float kHeatWastedDim = 0.3f;
// Width in texels of one bin's swatch in the legend (HEAT_SWATCH): 8 x 32 = 256 texels.
inline constexpr int kHeatSwatchTexels = 32;

// The bin of a count; NaN and negative counts fall in bin 0.
inline int heatBin(float count) {
    int bin = 0;
    for (int k = 1; k < kHeatBins; ++k)
        if (count >= float(kHeatBinEdges[std::size_t(k)])) bin = k;
    return bin;
}

// A bin's colour, 0..1 (bins outside 0..7 are clamped).
inline glm::vec3 heatBinColor(int bin) {
    bin = bin < 0 ? 0 : bin >= kHeatBins ? kHeatBins - 1 : bin;
    auto const& c = kHeatBinColors[std::size_t(bin)];
    return glm::vec3(float(c[0]), float(c[1]), float(c[2])) / 255.0f;
}

// What the heat map shows at a pixel where `evaluated` lights ran and `lit` of them lit it.
inline glm::vec3 heatMapColor(float evaluated, float lit) {
    float const share = evaluated > 0.0f ? glm::clamp(lit / evaluated, 0.0f, 1.0f) : 0.0f;
    return heatBinColor(heatBin(evaluated)) * glm::mix(kHeatWastedDim, 1.0f, share);
}

// The legend's label of a bin: its lowest count ("0", "1", "2", "4", ... "64+").
inline std::string heatBinLabel(int bin) {
    if (bin < 0 || bin >= kHeatBins) return "?";
    std::string s = std::to_string(kHeatBinEdges[std::size_t(bin)]);
    return bin == kHeatBins - 1 ? s + "+" : s;
}

// Every count a bin holds: "0", "1", "2-3", ... "32-63", "64+".
inline std::string heatBinRange(int bin) {
    if (bin < 0 || bin >= kHeatBins) return "?";
    int const lo = kHeatBinEdges[std::size_t(bin)];
    if (bin == kHeatBins - 1) return std::to_string(lo) + "+";
    int const hi = kHeatBinEdges[std::size_t(bin) + 1] - 1;
    return lo == hi ? std::to_string(lo) : std::to_string(lo) + "-" + std::to_string(hi);
}

// The quantity a count view shows: the lights-per-tile view always counts the tiled mode's lists;
// the heat map counts what the frame's mode evaluated at each pixel.
inline std::string_view heatQuantity(DebugView view, LightingMode mode) {
    if (view == DebugView::TileLights) return "lights per tile";
    switch (mode) {
        case LightingMode::Volumes:
            return "volumes per pixel";
        case LightingMode::Tiled:
        case LightingMode::ForwardPlus:
            return "lights per tile";
        case LightingMode::Clustered:
            return "lights per cluster";
        case LightingMode::Forward:
            return "nothing counted (forward has no G-buffer)";
        case LightingMode::Prepass:
            return "nothing counted (prepass's thin G-buffer is not counted over)";
        default:
            return "lights per pixel (every light)";
    }
}

}  // namespace gbl
