// File menu entries and dialogs for opening glTF scenes, and the loading progress window.
#pragma once

#include "model/scene_loading.h"

namespace gbl::ui {

// "Open scene…" and "Open recent" (call between BeginMenu("File") and EndMenu()).
void drawSceneMenuItems(SceneLoadingState& state);

// Opens the path dialog, prefilled with `prefill` (the menu item and Ctrl+O use it).
void openSceneDialog(SceneLoadingState& state, std::string const& prefill);

// The open dialog, the progress window of a running load (with Cancel) and the error dialog
// of a failed one. Requests go to state.requests; the window loop starts them.
void drawSceneLoadingUi(SceneLoadingState& state);

}  // namespace gbl::ui
