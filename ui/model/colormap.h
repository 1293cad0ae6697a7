// Colormaps for single-channel views (grey, turbo, viridis) and the legend ticks in data units.
// The same tables are in shaders/view_tools.glsl; tests/viewer_tools_gl_test.cpp checks they agree.
#pragma once

#include "core/view_params.h"

#include <glm/glm.hpp>

#include <string_view>
#include <vector>

namespace gbl::ui {

using gbl::kColormapNames;

// Colour of t (clamped to 0..1) under the map, linear RGB 0..1.
glm::vec3 colormap(Colormap map, float t);

struct LegendTick {
    float value = 0.0f;     // in data units
    float position = 0.0f;  // 0..1 along the legend (0 = black point, 1 = white point)
};

// Ticks at "round" values (1, 2 or 5 times a power of ten) between lo and hi, about `target` of
// them, always including both ends' positions when lo/hi are themselves round. Empty if hi <= lo
// or either is not finite.
std::vector<LegendTick> legendTicks(float lo, float hi, int target = 5);

}  // namespace gbl::ui
