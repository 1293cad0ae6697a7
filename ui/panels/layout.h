// Window layout: the default dock layout with a docking ImGui, the tiled fallback without.
#pragma once

#include "model/layout_state.h"

namespace gbl::ui {

// Called once per frame after NewFrame and the main menu bar: builds or restores the dock
// layout (docking builds), or does nothing (tiled builds position each window themselves).
void beginLayout(LayoutState& state);

// Called right before ImGui::Begin of an editor window: pins it to its tile in tiled builds,
// and gives docking builds nothing to do (the dock tree places it).
void placeWindow(EditorWindow window);

// Called right before ImGui::Begin of the Frame window (panel_frame.h): tiled builds pin it over
// the G-buffer strip while it is open (the strip is not drawn then); docking builds dock it as a
// tab beside the strip in the default layout.
void placeFrameWindow();

// Tiled builds: a handle on each boundary between windows; dragging one moves it (the model's
// dragSplit) and marks the layout file for saving. Called after every editor window, so the
// handles lie over their edges. Docking builds have the dock splitters and do nothing here.
void drawSplitHandles(LayoutState& state);

// Window flags for editor windows in this build (tiled windows cannot be moved or resized).
int editorWindowFlags();

}  // namespace gbl::ui
