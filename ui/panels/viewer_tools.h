// The viewer tools' widgets inside each G-buffer viewer cell (histogram, colormap and overlay
// selectors, region and diff statistics) and the magnifier window with go-to-pixel.
#pragma once

#include "model/viewer_state.h"

#include <imgui.h>

namespace gbl::ui {

// Overlay colours, as the view pass draws them (shaders/view_tools.glsl).
inline constexpr ImU32 kNaNColour = IM_COL32(255, 0, 255, 255);
inline constexpr ImU32 kInfColour = IM_COL32(0, 255, 0, 255);
inline constexpr ImU32 kNegativeColour = IM_COL32(0, 255, 255, 255);

// Header counts ("NaN 3  Inf 0  neg 12") once the tools have statistics.
void viewerHeaderCounts(ViewerState const& v, ViewerData const& d);
// The row of tool toggles: histogram, colormap, overlays, pin, diff.
void viewerToolsRow(ViewerState& v, ViewerData const& d);
// Histogram with draggable black/white points, the fit buttons and the colormap legend.
void viewerHistogram(ViewerState& v, ViewerData const& d);
// Region statistics and diff statistics, when a region is set / the diff is shown.
void viewerRegionAndDiff(ViewerState& v, ViewerData const& d);
// Magnifier window: the active viewer's texels around the picked texel.
void drawViewerMagnifier(GBufferPanelState& panel);
// Arrow keys step the picked texel; Ctrl+G opens go-to-pixel. Call inside the G-buffer window.
void viewerKeys(GBufferPanelState& panel);

}  // namespace gbl::ui
