// State of the Lights window and of the light animation, as plain values.
#pragma once

#include "core/point_light.h"
#include "scene/scene_data.h"

#include <cstdint>
#include <optional>
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
    // The plot's ghost: the selected light as it was when the last drag (or typed edit) of one of
    // its attenuation fields began (Kc, Kl, Kq, intensity, cut-off, colour: sameAttenuation), drawn
    // faint behind the curve so before and after can be compared. It stays after the drag, while
    // the light is as the drag left it; another drag starts a new one, and any other change of
    // those fields (undo, a preset, a script) or another selection drops it. trackPlotGhost keeps it.
    std::optional<PointLight> plotGhost;
    int plotGhostOf = -1;       // the light it belongs to
    PointLight plotGhostAfter;  // that light as the drag left it
    bool plotDragging = false;  // an attenuation field was held last frame
    std::string message;        // why the last edit or request was refused; empty when it was fine
    // Where the panel drew things this frame, for --log-frames (x, y, width, height in window
    // coordinates; 0 unless drawn and wholly in view): the attenuation plot and the Kq field; the
    // radius the plot marks and its ghost's (-1 when not drawn).
    glm::vec4 window{0.0f};  // the Lights window itself (0 while collapsed or hidden)
    glm::vec4 plotRect{0.0f};
    // The pixels the plot lacks of its least height at the top of the window (the layout grows the
    // window by them, panels/layout.h); -1 while no plot is drawn.
    float plotShortPx = -1.0f;
    glm::vec4 kqFieldRect{0.0f};
    float plotRadius = -1.0f;
    float plotGhostRadius = -1.0f;
    std::vector<float> plotLight;  // the plotted light's Kc, Kl, Kq, Imax, cut-off (empty when not drawn)
    // The plot shown beside the pointer while an attenuation field is dragged with the plot out of
    // view (window coordinates; 0 when not shown) and the radius it marks (-1 when not shown).
    glm::vec4 plotPopupRect{0.0f};
    float plotPopupRadius = -1.0f;
};

// Whether two lights have the same attenuation curve inputs: kind, Kc, Kl, Kq, intensity, cut-off
// and colour (Imax is intensity times the largest channel).
bool sameAttenuation(PointLight const& a, PointLight const& b);

// Once a frame, after the selected light's fields are drawn and its edit applied: `dragging`
// whether one of its attenuation fields is held (active, or released this frame), `before` the
// light as it was before this frame's edit, `now` as it is after.
void trackPlotGhost(LightsPanelState& state, bool dragging, PointLight const& before, PointLight const& now);

// The ghost to draw for the selected light `now`: the light before the drag, unless there is none
// or it draws the same curve.
PointLight const* shownPlotGhost(LightsPanelState const& state, PointLight const& now);

}  // namespace gbl::ui
