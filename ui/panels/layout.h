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

// Called after every editor window: notes where each one is docked and its tab (state.docks).
void recordDocks(LayoutState& state);

}  // namespace gbl::ui
