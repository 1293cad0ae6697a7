// The light-by-light scrubber: how many lights the frame accumulates and whether it shows the
// last one's own contribution. Plain values; the editor turns them into FrameInput fields.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>

namespace gbl::ui {

struct AccumulateState {
    bool enabled = false;
    int count = 0;               // lights accumulated, 0 (ambient alone) .. the light count
    bool contribution = false;   // show light `count` alone, without ambient
    glm::vec4 sliderRect{0.0f};  // where the viewport drew the slider (window coordinates; --log-frames)

    bool operator==(AccumulateState const&) const = default;
};

// Moves the scrubber by `delta` lights (the arrow keys), kept within 0..lightCount.
inline void stepAccumulation(AccumulateState& a, int delta, int lightCount) {
    a.count = std::clamp(a.count + delta, 0, std::max(lightCount, 0));
}

}  // namespace gbl::ui
