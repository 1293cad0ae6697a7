// The attenuation plot's ghost: the light as it was before the current drag.
#include "model/lights_state.h"

namespace gbl::ui {

bool sameAttenuation(PointLight const& a, PointLight const& b) {
    return a.kind == b.kind && a.kc == b.kc && a.kl == b.kl && a.kq == b.kq && a.intensity == b.intensity &&
           a.threshold == b.threshold && a.color == b.color;
}

void trackPlotGhost(LightsPanelState& state, bool dragging, PointLight const& before, PointLight const& now) {
    if (dragging) {
        // A new drag (or the same drag moved to another light) starts from the light as it was.
        if (!state.plotDragging || state.plotGhostOf != state.selected) {
            state.plotGhost = before;
            state.plotGhostOf = state.selected;
        }
        state.plotDragging = true;
        state.plotGhostAfter = now;
        return;
    }
    state.plotDragging = false;
    if (state.plotGhost && (state.plotGhostOf != state.selected || !sameAttenuation(now, state.plotGhostAfter))) {
        state.plotGhost.reset();
        state.plotGhostOf = -1;
    }
}

PointLight const* shownPlotGhost(LightsPanelState const& state, PointLight const& now) {
    if (!state.plotGhost || state.plotGhostOf != state.selected || sameAttenuation(*state.plotGhost, now))
        return nullptr;
    return &*state.plotGhost;
}

}  // namespace gbl::ui
