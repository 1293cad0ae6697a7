// State of the Lights window and of the light animation, as plain values.
#pragma once

#include "core/point_light.h"
#include "scene/scene_data.h"

#include <cstdint>
#include <string>
#include <vector>

namespace gbl::ui {

struct LightAnimation {
    bool enabled = false;
    float speed = 1.0f;  // multiplies real time
    float time = 0.0f;   // seconds of animation so far; what orbitLights is evaluated at
};

struct LightsPanelState {
    int selected = -1;
    int listShows = -1;  // the selection the list last scrolled to; a new one (viewport pick) scrolls
    int randomCount = 16;
    std::uint32_t randomSeed = 20240611u;
    bool plotLogScale = false;
    // The attenuation plot's distance axis held at plotAxisMax instead of following the radius,
    // so a change of Kq shows as a change of the curve.
    bool plotFixedAxis = false;
    float plotAxisMax = 0.0f;
    std::string message;  // why the last edit or request was refused; empty when it was fine
};

}  // namespace gbl::ui
