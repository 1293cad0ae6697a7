// Sessions inside the editor: taking a Session (ui/session.h) from the editor state and putting
// one back, the File menu's Open/Save popups, and the offer to restore a crashed run's autosave.
#pragma once

#include "editor_state.h"
#include "recovery.h"
#include "session.h"

#include <optional>
#include <string>

namespace gbl::ui {

struct SessionUiState {
    std::string path;              // file of the last successful open or save
    char pathInput[512] = "session.json";  // the popups' path field
    bool openRequested = false;    // File > Open...: the loop opens the popup
    bool saveRequested = false;
    std::optional<std::string> openPath;  // Open was confirmed with this path this frame
    std::optional<std::string> savePath;
    std::string message;           // the last open/save result, shown in the popup and the log

    std::optional<UncleanExit> recoveryOffer;  // a previous run's autosave, offered at start-up
    bool acceptRecovery = false;   // the user (or a UI script) chose to restore it this frame
    bool declineRecovery = false;
    bool recoveryShown = false;    // the offer window was focused once
};

// What a session file stores of the current editor state. defaultSceneLights is what the
// default scene was built with (the lights themselves are stored one by one anyway).
Session sessionFromEditor(EditorState const& state, int defaultSceneLights);

// Copies the session's camera, lights, pipeline, viewer settings and animation into the
// state. The scene itself is loaded by the caller (it needs the renderer).
void applySessionValues(Session const& session, EditorState& state);

// The Open/Save popups and the recovery offer; results land in `ui` for the loop to act on.
void drawSessionPopups(SessionUiState& ui);

}  // namespace gbl::ui
