// File menu entries and dialogs for opening glTF scenes, and the loading progress window.
#pragma once

#include "model/scene_loading.h"

namespace gbl::ui {

// "Open scene…", "Open recent", "Open G-buffer…" and "Close G-buffer" (call between
// BeginMenu("File") and EndMenu()).
void drawSceneMenuItems(SceneLoadingState& state);

// Opens the path dialog, prefilled with `prefill` (the menu item and Ctrl+O use it).
void openSceneDialog(SceneLoadingState& state, std::string const& prefill);

// File > Open G-buffer's dialog: a manifest, or a folder (Open with no name opens the folder shown).
void openGBufferDialog(GBufferOpenState& state);

// The open dialogs, the progress window of a running load (with Cancel) and the error dialog
// of a failed one. Requests go to state.requests; the window loop starts them.
void drawSceneLoadingUi(SceneLoadingState& state);

}  // namespace gbl::ui
