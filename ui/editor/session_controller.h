// The editor's session life cycle in one place: open/save, undo/redo, autosave with crash
// recovery, and exports. The window loop owns one and calls it at fixed points of the frame.
#pragma once

#include "frame_export.h"
#include "model/editor_state.h"
#include "model/undo.h"
#include "panels/panel_session.h"
#include "renderer.h"
#include "session/recovery.h"
#include "session/session.h"

#include <functional>
#include <optional>
#include <string>

namespace gbl::ui {

// Loads `scene` ("default" or a glTF path; defaultSceneLights for the default scene) into the
// renderer and the state (scene source, bounds, orbit centre). On failure returns one sentence;
// the caller restores the state, and the renderer keeps its scene (Renderer::setScene's rule).
using SceneLoader = std::function<std::optional<std::string>(std::string const& scene, int defaultSceneLights)>;

class SessionController {
public:
    // recovery: where markers and autosaves go; nullopt runs without crash recovery.
    SessionController(Clock clock, std::optional<RecoveryDir> recovery, long pid, AutosaveTiming timing = {});

    // After the first scene is loaded: starts the undo history, marks this run and looks for
    // an editor that did not exit cleanly (its session is then offered in panel.recoveryOffer).
    void start(EditorState& state, int defaultSceneLights);

    // Once per frame after the panels ran. editing: a widget is held (a drag in progress).
    void afterFrame(EditorState& state, bool editing);

    void undo(EditorState& state);
    // A lesson step (or leaving a lesson) was applied: one undo entry of its own (UndoStack::commit).
    void commitLessonStep(EditorState const& state);
    // A lesson shows states of its own: what it sets is not an edit Quit would ask about. Called
    // before the first step (remembers whether edits were unsaved then), after each step or
    // prediction is applied (what it shows is the new baseline) and after leaving.
    void lessonStarting(EditorState const& state);
    void lessonStepShown(EditorState const& state);
    void lessonLeft();
    void redo(EditorState& state);
    // A new scene replaced the lights: the old scene's edits must not be undone into it.
    void sceneChanged(EditorState const& state);

    // All or nothing: on any error the state is as before and the error is returned.
    std::optional<std::string> openSession(std::string const& path, EditorState& state, SceneLoader const& load);
    std::optional<std::string> saveSession(std::string const& path, EditorState const& state);
    // File > New: the default scene with its lights and default settings, untitled.
    std::optional<std::string> newSession(EditorState& state, SceneLoader const& load);
    std::optional<std::string> restoreRecovery(EditorState& state, SceneLoader const& load);
    void discardRecovery();

    // Carries out what the File menu dialogs asked for. `frame` describes the frame on screen
    // (for Export all); the result is logged and shown in the dialog.
    void handle(SessionRequest const& request, EditorState& state, Renderer& renderer, FrameExport const& frame,
                SceneLoader const& load);

    // File > Export all (creates the folder) and the viewer export; error sentence or nullopt.
    static std::optional<std::string> exportAll(std::string const& dir, Renderer& renderer, FrameExport const& frame);
    static std::optional<std::string> exportViewer(int viewer, bool raw, std::string const& path,
                                                   EditorState const& state, Renderer& renderer);

    // Writes the recovery session now if a change is pending and there are unsaved edits (used
    // before risky operations and by tests); returns true when a file was written. With no
    // unsaved edits left, this run's recovery session is removed instead: only edits are offered.
    bool autosaveNow(EditorState const& state);
    // The clean-exit path: removes this run's marker and recovery session.
    void endCleanly();

    // Edits since the session was last opened or saved (or since start) that Quit, New and Open
    // would discard. Looking around is not an edit: the camera and the animation clock are left out.
    bool hasUnsavedEdits(EditorState const& state) const;

    // What a session stores when the editor shows something in place of the scene (an imported
    // G-buffer, model/gbuffer_opening.h): the state with the scene's camera and lights put back, or
    // nullopt when the scene is shown. Saving, autosaving and the unsaved-edits question then speak of
    // the scene, never of the G-buffer's lights.
    using SceneBehind = std::function<std::optional<EditorState>(EditorState const&)>;
    void setSceneBehind(SceneBehind f) { sceneBehind_ = std::move(f); }

    int autosaves() const { return autosaves_; }
    std::optional<RecoveryDir> const& recovery() const { return recovery_; }
    std::string recoveryPath() const { return recovery_ ? recovery_->sessionPath(pid_) : std::string(); }
    UndoStack const& history() const { return undo_; }

    SessionPanelState panel;

private:
    std::optional<std::string> applyLoaded(Session const& session, EditorState& state, SceneLoader const& load);
    std::string editsText(EditorState const& state) const;
    void offerText(EditorState& state, UncleanExit const& u);  // panel.recovery* and the log line
    void forgetAutosave();                                     // this run's autosave, once nothing is unsaved
    Session captured(EditorState const& state) const;          // captureSession of the scene behind (sceneBehind_)
    SceneBehind sceneBehind_;
    std::optional<std::string> lessonBaseline_;  // the edits text of the lesson step shown
    bool editsBeforeLesson_ = false;

    Clock clock_;
    std::optional<RecoveryDir> recovery_;
    long pid_ = 0;
    UndoStack undo_;
    AutosaveTimer autosave_;
    int defaultSceneLights_ = 32;
    std::string lastSeen_;    // session text at the last change check
    std::string lastSaved_;   // session text in the recovery file
    std::string savedEdits_;  // editsText when the session was last opened or saved by the user
    double lastCheck_ = -1e300;
    int autosaves_ = 0;
    bool autosaveWritten_ = false;  // this run's recovery session exists
};

}  // namespace gbl::ui
