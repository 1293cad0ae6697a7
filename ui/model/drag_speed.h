// Drag speeds for number fields: proportional to the value, so a drag changes a value by about the
// same share per pixel whatever its size (Kq's useful range spans 0.001..2, a position's 0.1..100).
#pragma once

#include <algorithm>
#include <cmath>

namespace gbl::ui {

// Share of the value one pixel of drag changes.
inline constexpr float kProportionalDragShare = 0.01f;
// Kc, Kl and Kq are read on a log scale (the plot's log axis, presets a factor of ~2 apart), so
// a pixel multiplies them by 1.02: 1/10 to 10x in about 116 pixels each way.
inline constexpr float kLogDragShare = 0.02f;

// Speed for ImGui's DragFloat this frame: `share` of |value|, but at least `floor` so a value at 0
// can be dragged away from it.
inline float proportionalDragSpeed(float value, float floor, float share = kProportionalDragShare) {
    return std::max(std::abs(value) * share, floor);
}

// Pixels of drag (at proportionalDragSpeed with kLogDragShare, re-evaluated each pixel) to go
// from `from` to `to`, both > 0: what the drag feels like, for the test and the tooltip.
inline int pixelsToDrag(float from, float to, float share = kLogDragShare) {
    return int(std::ceil(std::abs(std::log(double(to) / double(from))) / std::log1p(double(share))));
}

}  // namespace gbl::ui
