// Window layout: the default dock layout (DockBuilder) over the main viewport.
#pragma once

#include "model/layout_state.h"

namespace gbl::ui {

// Called once per frame after NewFrame and the main menu bar: builds the default dock layout on a
// first start (no dock tree in imgui.ini) or when "Reset layout" asked for it, then the dock space
// over the main viewport. Windows can then be undocked, re-docked and tabbed; imgui.ini keeps them.
// Needs io.ConfigFlags with ImGuiConfigFlags_DockingEnable (gui_util.h, enableConfigFlags).
void beginLayout(LayoutState& state);

// Called right before ImGui::Begin of the Frame window (panel_frame.h): the default layout docks it
// as a tab beside the strip; a layout restored from an older imgui.ini has no place for it, so it
// floats at a size that shows a few passes.
void placeFrameWindow();

// Called after `window` was drawn: while it `wants` the height and lacks `shortPx` pixels (the
// Lessons window its region's least lines, LessonState::regionShortPx; the Lights window its
// plot's least height), its dock node takes that height from the nodes above and below it in its
// column (each keeps a tab and `keepLines` lines), on the frames after it first wanted it, after
// `key` (what it shows) changed, the window resized or the UI scale changed; the user's drags in
// between stand. When it no longer wants the height the column's heights are put back as they were.
void fitWindowHeight(DockHeightFit& fit, EditorWindow window, bool wants, long key, float shortPx, int keepLines = 1);

// Called after the G-buffer strip was drawn, on the frames after the default layout was built or
// the window resized (StripFit): the strip's dock node takes the height its viewers' images need at
// their width and the frame's aspect (`imageArea`, a viewer's cell below its toolbar; `frameSize`,
// the frame they show: the viewport's image as drawn, which the next frame takes), or gives its spare height to the
// band above; the user's drags in between stand.
void fitStripHeight(StripFit& fit, glm::vec2 imageArea, glm::ivec2 frameSize);

// Called after every editor window: notes where each one is docked and its tab (state.docks).
void recordDocks(LayoutState& state);

}  // namespace gbl::ui
