// File menu entries and dialogs for sessions, export and crash recovery. The dialogs only
// collect what the user asked for; the window loop carries it out (it owns renderer and scene).
#pragma once

#include "model/file_browser.h"
#include "session/recovery.h"

#include <glm/glm.hpp>

#include <array>
#include <optional>
#include <string>

namespace gbl::ui {

enum class SessionDialog { None, Open, Save, ExportAll, ExportViewer };

struct SessionPanelState {
    std::string currentPath;  // session last opened or saved ("" = untitled)
    SessionDialog dialog = SessionDialog::None;
    bool dialogJustOpened = false;             // focus the path field on the first frame
    std::array<char, 1024> pathInput{};        // the export dialogs' text field
    FileBrowserState browser;                  // Open session and Save session as
    std::optional<std::string> openDropped;    // a session file dropped (or picked in the browser): open it
    int exportViewer = 0;                      // index into the G-buffer viewers
    bool exportRaw = false;                    // viewer export: raw attachment as EXR instead of PNG
    std::optional<UncleanExit> recoveryOffer;  // shown as a modal until answered
    std::string recoveryTitle;                 // "Your changes from 3 minutes ago were not saved."
    std::string recoveryWhy;                   // one line about the offered session (lights, scene)
    std::string recoveryCause;                 // natively: the editor that did not exit cleanly, its file
    std::string message;                       // result of the last request, shown in the dialog
    bool saveRequested = false;                // "Save session" (or Ctrl+S) with a known path: no dialog
    bool closePending = false;                 // the request succeeded: close the dialog next frame
    glm::vec4 exportAllItemRect{0.0f};         // File > "Export all..." while the menu is open, for the frame log
};

enum class SessionRequestKind {
    None,
    Open,
    Save,
    ExportAll,
    ExportViewerPng,
    ExportViewerExr,
    Restore,
    DiscardRecovery
};

struct SessionRequest {
    SessionRequestKind kind = SessionRequestKind::None;
    std::string path;  // file or folder the user chose
    int viewer = 0;    // viewer exports
};

// Menu items for the File menu (call between BeginMenu("File") and EndMenu()).
void drawSessionMenuItems(SessionPanelState& state);
// Opens a dialog with the path field prefilled (the menu items and keyboard shortcuts use it);
// Open and Save open the file browser in the folder of `prefill` (the working folder if relative).
void openSessionDialog(SessionPanelState& state, SessionDialog dialog, std::string const& prefill);

// Reports how the window loop carried out a request: success closes the dialog, an error keeps
// it open with the message so the user can correct the path.
void finishSessionRequest(SessionPanelState& state, std::optional<std::string> const& error);

// Draws the open dialog and the recovery offer, if any; returns what the user confirmed this frame.
SessionRequest drawSessionDialogs(SessionPanelState& state);

}  // namespace gbl::ui
