// Between the editor's state and session files: what a session captures of a running editor,
// and how a loaded session is applied to it (the scene itself is loaded by the window loop).
#pragma once

#include "model/editor_state.h"
#include "model/undo.h"
#include "session/session.h"

namespace gbl::ui {

// The session describing the editor right now. defaultSceneLights: the light count the
// default scene was opened with (kept so the file says how the session started).
Session captureSession(EditorState const& state, int defaultSceneLights);

// Applies camera, lights, pipeline, viewer settings and animation. The caller has already
// made sure the renderer shows session.scene. The orbit target is placed ahead of the
// session's camera, the selection is kept when it is still a valid index.
void applySessionValues(Session const& session, EditorState& state);

// What undo tracks of the editor.
UndoSnapshot undoSnapshot(EditorState const& state);
void applyUndoSnapshot(UndoSnapshot const& snapshot, EditorState& state);

}  // namespace gbl::ui
