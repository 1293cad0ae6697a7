// Defaults of the G-buffer viewers and the view each one asks for.
#include "model/viewer_state.h"


namespace gbl::ui {

std::array<ViewerState, 5> GBufferPanelState::defaultViewers() {
    std::array<ViewerState, 5> v;
    for (std::size_t i = 0; i < v.size(); ++i) v[i].kind = ViewerKind(i);
    // Positions are world units, not colours: start with a range that shows a scene of a few
    // tens of units and refit to the data.
    v[0].rangeMin = -20.0f;
    v[0].rangeMax = 20.0f;
    v[0].autoFit = true;
    v[3].channelMask = 0x1;  // specular is one value, drawn as grey
    v[4].channelMask = 0x1;
    v[4].autoFit = true;
    return v;
}

DebugView viewerDebugView(ViewerState const& viewer) {
    switch (viewer.kind) {
    case ViewerKind::Position: return DebugView::Position;
    case ViewerKind::Normal: return DebugView::Normal;
    case ViewerKind::Albedo: return DebugView::Albedo;
    case ViewerKind::Specular: return DebugView::Specular;
    case ViewerKind::Depth: return viewer.linearDepth ? DebugView::DepthLinear : DebugView::Depth;
    }
    return DebugView::Final;
}

ViewParams viewerParams(ViewerState const& viewer) {
    ViewParams p;
    p.view = viewerDebugView(viewer);
    p.channelMask = viewer.channelMask == 0 ? 0x7u : viewer.channelMask;
    p.rangeMin = viewer.rangeMin;
    p.rangeMax = viewer.rangeMax;
    p.normalDisplay = viewer.normalDisplay;
    return p;
}

}  // namespace gbl::ui
