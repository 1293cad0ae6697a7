// Lights window: the light list, the selected light's parameters, its attenuation plot, presets,
// random lights and animation.
#pragma once

#include <optional>
#include <vector>
#include "core/point_light.h"
#include "model/lights_state.h"
#include "scene/scene_data.h"

namespace gbl::ui {

// Edits `lights` in place through the validated operations of light_list.h. pixelDistance: the
// inspected pixel's distance from the selected light, marked on the attenuation plot.
void drawLightsPanel(LightsPanelState& state, std::vector<PointLight>& lights, LightAnimation& animation,
                     Bounds const& sceneBounds, std::optional<float> pixelDistance = std::nullopt);

}  // namespace gbl::ui
