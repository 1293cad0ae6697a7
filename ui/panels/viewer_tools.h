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

// The narrowest a G-buffer viewer cell may be: its one-line toolbar (the longest name, the
// channel toggles and "...") plus the cell's padding. The strip scrolls sideways below five of
// these rather than cut the toolbar off.
float viewerCellMinWidth();
// Puts the next item of width w on the current line when it ends before `right`, else on a new one.
void sameLineIfRoom(float w, float right);

// Four small toggles R G B A; a single channel alone is shown as grey by the view pass.
void viewerChannelToggles(ViewerState& v);
// Channel toggles, range with Fit and auto, and the kind's own options (normals, depth; the
// depth viewer's stencil switch when stencilChoice).
// msaaSamples > 0 (the frame ran msaa) adds the sample selector (viewerSampleSelector).
void viewerControls(ViewerState& v, bool stencilChoice, int msaaSamples = 0);
// msaa (issue 47): a small combo of "all" and each of `samples` samples, editing `sample` (-1 all);
// greyed out with the reason where not `offered`; nothing while samples is 0. `id`: its ImGui id.
void viewerSampleSelector(int& sample, int samples, bool offered, char const* id);
// Outline of the texels a (inclusive) .. b (exclusive) on an image drawn at p0 with size full.
void outlineTexels(ImDrawList* dl, ImVec2 p0, ImVec2 full, glm::ivec2 imageSize, glm::ivec2 a, glm::ivec2 b,
                   ImU32 colour);
// The pixel inspector's locked pixel on an image drawn at p0 with size full: a black-and-white
// cross with a gap, so the pixel itself stays visible over any picture. The caller clips.
void markLockedPixel(ImDrawList* dl, ImVec2 p0, ImVec2 full, glm::ivec2 imageSize, glm::ivec2 pixel);
// Header counts ("NaN 3  Inf 0  neg 12") once the tools have statistics.
void viewerHeaderCounts(ViewerState const& v, ViewerData const& d);
// The row of tool toggles: histogram, colormap, overlays, pin, diff.
void viewerToolsRow(ViewerState& v, ViewerData const& d);
// Histogram with draggable black/white points, the fit buttons and the colormap legend.
void viewerHistogram(ViewerState& v, ViewerData const& d);
// The region rows ("no region", or the region and its statistics; a row of fixed height while a
// Shift+drag is on) and the diff statistics when the diff is shown.
void viewerRegionAndDiff(ViewerState& v, ViewerData const& d);
// The viewport's tools (issue 15: the viewer tools "in the viewport when it shows an
// attachment"): a Tools toggle while the view is a G-buffer attachment or the lit frame, and
// while on a "..." popover with the same controls as a G-buffer viewer's. Call on a toolbar
// row of the viewport; it never adds a row.
void viewportToolsRow(ViewportTools& tools, DebugView view, int msaaSamples = 0);
// Call right after the viewport's image item: Shift+drag sets the region, Shift+right-click the
// magnifier's texel; draws their outlines. True when the mouse is the tools' (the camera must
// not move with it).
bool viewportToolsImage(ViewportTools& tools, ImVec2 origin, ImVec2 size, glm::ivec2 imageSize);
// Magnifier window: the active viewer's texels around the picked texel (activeViewer
// kViewportViewer: the viewport's tools).
void drawViewerMagnifier(GBufferPanelState& panel, ViewportTools& viewport);
// Arrow keys step the picked texel; Ctrl+G opens go-to-pixel. Call inside the G-buffer window.
void viewerKeys(GBufferPanelState& panel);

}  // namespace gbl::ui
