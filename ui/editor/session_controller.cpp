// Session life cycle of the editor: history, autosave, recovery, file requests.
#include "session_controller.h"

#include "model/browser_files.h"
#include "model/zip_archive.h"
#include "session/atomic_file.h"
#include "session/editor_session.h"
#include "viewer_export.h"

#include <algorithm>
#include <filesystem>

namespace gbl::ui {

namespace fs = std::filesystem;

namespace {
// How often the session text is compared with the last one to notice changes: often enough for
// the autosave's 3-second quiet period, rare enough that thousands of lights cost nothing.
constexpr double kChangeCheckSeconds = 0.5;

// The browser's Export all: the folder's own name ("export" for "export" or "out/export/"), which
// names the zip and the folder inside it.
std::string exportFolderName(std::string const& dir) {
    fs::path const p(dir);
    std::string name = p.filename().string();
    if (name.empty()) name = p.parent_path().filename().string();
    return name.empty() || name == "." || name == ".." ? "export" : name;
}

std::string exportZipName(std::string const& dir) {
    return "gbuffer-lab-" + exportFolderName(dir) + ".zip";
}
}  // namespace

SessionController::SessionController(Clock clock, std::optional<RecoveryDir> recovery, long pid, AutosaveTiming timing)
    : clock_(std::move(clock)), recovery_(std::move(recovery)), pid_(pid), autosave_(clock_, timing) {}

void SessionController::start(EditorState& state, int defaultSceneLights) {
    defaultSceneLights_ = defaultSceneLights;
    undo_.reset(undoSnapshot(state));
    lastSeen_ = lastSaved_ = sessionToJson(captured(state));
    savedEdits_ = editsText(state);
    if (!recovery_) return;
    // Look before marking: our own marker must not count as a crash.
    auto const unclean = recovery_->uncleanExits();
    for (auto const& u : unclean) {
        if (!u.sessionPath.empty() && !panel.recoveryOffer) {
            panel.recoveryOffer = u;
            offerText(state, u);
        } else {
            recovery_->discard(u);  // nothing saved, or an older crash than the one offered
        }
    }
    if (auto err = recovery_->beginRun(pid_)) {
        logMessage(state.log, "crash recovery is off: " + *err, true);
        recovery_.reset();
    }
}

void SessionController::offerText(EditorState& state, UncleanExit const& u) {
    // An autosave holds edits that were never saved (autosaveNow writes nothing else), so the
    // offer speaks of them. In the browser closing or reloading the tab is the page's normal end:
    // no crash is named there, and the path is the page's own file system, of no use to a student.
    std::string const age = ageInWords(fileClockSeconds() - u.modifiedSeconds);
    panel.recoveryTitle = "Your changes from " + age + " were not saved.";
    SessionLoad const peek = loadSession(u.sessionPath);
    if (peek.session) {
        std::string const scene = peek.session->scene == "default"
                                      ? std::string("the default scene")
                                      : "the scene " + fs::path(peek.session->scene).filename().string();
        panel.recoveryWhy = "They can be restored: " + std::to_string(peek.session->lights.size()) + " lights, " +
                            scene + (kInBrowser ? " (kept in this browser)." : ".");
    } else {
        panel.recoveryWhy = "They cannot be read back: " + peek.error;
    }
    panel.recoveryCause = kInBrowser ? std::string()
                                     : "gbuffer-lab (pid " + std::to_string(u.pid) +
                                           ") did not exit cleanly; its autosave is " + u.sessionPath;
    logMessage(state.log, kInBrowser ? "your unsaved changes from " + age + " are offered to restore"
                                     : "an earlier editor (pid " + std::to_string(u.pid) +
                                           ") did not exit cleanly; its unsaved changes from " + age + " are offered");
}

void SessionController::forgetAutosave() {
    if (!recovery_ || !autosaveWritten_) return;
    recovery_->forgetSession(pid_);
    autosaveWritten_ = false;
}

void SessionController::afterFrame(EditorState& state, bool editing) {
    double const now = clock_();
    undo_.observe(state.lights, state.pipeline, editing, now);
    if (!recovery_ || now - lastCheck_ < kChangeCheckSeconds) {
        if (recovery_ && autosave_.due()) autosaveNow(state);
        return;
    }
    lastCheck_ = now;
    std::string text = sessionToJson(captured(state));
    if (text != lastSeen_) {
        lastSeen_ = std::move(text);
        if (lastSeen_ != lastSaved_) autosave_.changed();
    }
    if (autosave_.due()) autosaveNow(state);
}

bool SessionController::autosaveNow(EditorState const& state) {
    if (!recovery_ || !autosave_.pending()) return false;
    std::string const text = sessionToJson(captured(state));
    if (!hasUnsavedEdits(state)) {
        // Nothing the student changed and did not save (looking around, a lesson's own steps, or
        // edits saved or undone since): a reload or a crash then has nothing to offer.
        forgetAutosave();
        lastSaved_ = lastSeen_ = text;
        autosave_.saved();
        return false;
    }
    if (auto err = writeFileAtomically(recovery_->sessionPath(pid_), text)) {
        autosave_.failed();
        return false;
    }
    lastSaved_ = lastSeen_ = text;
    autosave_.saved();
    autosaveWritten_ = true;
    ++autosaves_;
    return true;
}

void SessionController::undo(EditorState& state) {
    if (auto s = undo_.undo(undoSnapshot(state), clock_())) applyUndoSnapshot(*s, state);
}

void SessionController::commitLessonStep(EditorState const& state) {
    undo_.commit(undoSnapshot(state), clock_());
}

void SessionController::lessonStarting(EditorState const& state) {
    if (!lessonBaseline_) editsBeforeLesson_ = hasUnsavedEdits(state);
}

void SessionController::lessonStepShown(EditorState const& state) {
    lessonBaseline_ = editsText(state);
}

void SessionController::lessonLeft() {
    lessonBaseline_.reset();
    editsBeforeLesson_ = false;
}

void SessionController::redo(EditorState& state) {
    if (auto s = undo_.redo(undoSnapshot(state), clock_())) applyUndoSnapshot(*s, state);
}

std::optional<std::string> SessionController::applyLoaded(Session const& session, EditorState& state,
                                                          SceneLoader const& load) {
    // The state is copied first so a scene that fails to load leaves everything as it was.
    EditorState const before = state;
    std::string const scene =
        session.scene == "default" && session.defaultSceneGlass ? std::string(kDefaultSceneGlass) : session.scene;
    bool const sameScene =
        scene == state.sceneName() && (session.scene != "default" || session.defaultSceneLights == defaultSceneLights_);
    if (!sameScene) {
        if (auto err = load(scene, session.defaultSceneLights)) {
            state = before;
            return err;
        }
    }
    applySessionValues(session, state);
    defaultSceneLights_ = session.defaultSceneLights;
    undo_.reset(undoSnapshot(state));
    return std::nullopt;
}

std::optional<std::string> SessionController::newSession(EditorState& state, SceneLoader const& load) {
    EditorState const before = state;
    if (auto err = load("default", defaultSceneLights_)) {
        state = before;
        return err;
    }
    state.pipeline = PipelineSettings{};
    state.animation = LightAnimation{};
    state.lightsPanel.selected = -1;
    undo_.reset(undoSnapshot(state));
    panel.currentPath.clear();
    savedEdits_ = editsText(state);
    forgetAutosave();
    logMessage(state.log, "new session");
    return std::nullopt;
}

Session SessionController::captured(EditorState const& state) const {
    if (sceneBehind_) {
        if (std::optional<EditorState> const scene = sceneBehind_(state))
            return captureSession(*scene, defaultSceneLights_);
    }
    return captureSession(state, defaultSceneLights_);
}

std::string SessionController::editsText(EditorState const& state) const {
    Session session = captured(state);
    session.camera = Camera{};
    session.animation.time = 0.0f;
    // Nor is a range that auto-fit refits from the data, or what a viewer last read.
    auto const settingsOnly = [](ViewerState& v) {
        if (v.autoFit) v.rangeMin = 0.0f, v.rangeMax = 1.0f;
        v.lastFitFrame = -1;
        v.imageSize = glm::ivec2(0);
        v.fitRequested = v.percentileFitRequested = v.regionFitRequested = v.pinRequested = false;
    };
    for (ViewerState& v : session.viewers) settingsOnly(v);
    settingsOnly(session.viewportViewer);
    return sessionToJson(session);
}

bool SessionController::hasUnsavedEdits(EditorState const& state) const {
    // In a lesson: the edits from before it (they wait in its return state), or edits made since
    // its step was shown.
    if (lessonBaseline_) return editsBeforeLesson_ || editsText(state) != *lessonBaseline_;
    return editsText(state) != savedEdits_;
}

void SessionController::sceneChanged(EditorState const& state) {
    undo_.reset(undoSnapshot(state));
}

std::optional<std::string> SessionController::openSession(std::string const& path, EditorState& state,
                                                          SceneLoader const& load) {
    // Refusals are logged here (the Log window and the menu bar show them) for every caller:
    // the File menu, --session and UI scripts.
    SessionLoad const loaded = loadSession(path);
    if (!loaded.session) {
        logMessage(state.log, loaded.error, true);
        return loaded.error;
    }
    if (auto err = applyLoaded(*loaded.session, state, load)) {
        std::string const message = path + ": " + *err;
        logMessage(state.log, message, true);
        return message;
    }
    panel.currentPath = path;
    savedEdits_ = editsText(state);
    forgetAutosave();
    logMessage(state.log, "opened session " + path);
    return std::nullopt;
}

std::optional<std::string> SessionController::saveSession(std::string const& path, EditorState const& state) {
    if (auto err = ui::saveSession(path, captured(state))) return err;
    panel.currentPath = path;
    savedEdits_ = editsText(state);
    forgetAutosave();       // saved: a reload or a crash now loses nothing
    if (lessonBaseline_) {  // saved mid-lesson: what is shown is in the file now
        lessonBaseline_ = savedEdits_;
        editsBeforeLesson_ = false;
    }
    return std::nullopt;
}

std::optional<std::string> SessionController::restoreRecovery(EditorState& state, SceneLoader const& load) {
    if (!panel.recoveryOffer) return std::string("there is no session to recover");
    UncleanExit const offer = *panel.recoveryOffer;
    SessionLoad const loaded = loadSession(offer.sessionPath);
    std::optional<std::string> err = loaded.session ? applyLoaded(*loaded.session, state, load) : loaded.error;
    // Restored or unreadable, the offer is answered: it is not made again at the next start.
    // The restored state is autosaved under this run as soon as the check notices it.
    panel.recoveryOffer.reset();
    if (!err) {
        recovery_->discard(offer);
        logMessage(state.log, "restored the unsaved changes");
        lastSaved_.clear();  // make the restored state this run's first autosave
        lastCheck_ = -1e300;
    } else {
        logMessage(state.log, "could not restore the recovered session: " + *err, true);
    }
    return err;
}

void SessionController::discardRecovery() {
    if (panel.recoveryOffer && recovery_) recovery_->discard(*panel.recoveryOffer);
    panel.recoveryOffer.reset();
}

void SessionController::handle(SessionRequest const& request, EditorState& state, Renderer& renderer,
                               FrameExport const& frame, SceneLoader const& load) {
    std::optional<std::string> err;
    std::string done;
    switch (request.kind) {
        case SessionRequestKind::None:
            return;
        case SessionRequestKind::Open:
            err = openSession(request.path, state, load);
            break;
        case SessionRequestKind::Save:
            err = saveSession(request.path, state);
            done = "saved session " + request.path;
            break;
        case SessionRequestKind::ExportAll:
            err = exportAll(request.path, renderer, frame);
            done = kInBrowser ? "exported the frame as " + exportZipName(request.path) + " (offered as a download)"
                              : "exported the frame to " + request.path;
            break;
        case SessionRequestKind::ExportViewerPng:
        case SessionRequestKind::ExportViewerExr:
            err = exportViewer(request.viewer, request.kind == SessionRequestKind::ExportViewerExr, request.path, state,
                               renderer);
            done = "exported a viewer to " + request.path;
            break;
        case SessionRequestKind::Restore:
            err = restoreRecovery(state, load);
            break;
        case SessionRequestKind::DiscardRecovery:
            discardRecovery();
            logMessage(state.log, "discarded the recovered session");
            return;
    }
    // In the browser a saved session or an exported viewer is also offered as a download: the
    // page's file system lives in memory. (Export all offers its zip itself.)
    bool const download = request.kind == SessionRequestKind::Save ||
                          request.kind == SessionRequestKind::ExportViewerPng ||
                          request.kind == SessionRequestKind::ExportViewerExr;
    if (!err && download && offerDownload(request.path)) done += " (offered as a download)";
    if (err && request.kind != SessionRequestKind::Open && request.kind != SessionRequestKind::Restore)
        logMessage(state.log, *err, true);  // open and restore log their own refusals
    else if (!done.empty())
        logMessage(state.log, done);
    finishSessionRequest(panel, err);
}

std::optional<std::string> SessionController::exportAll(std::string const& dir, Renderer& renderer,
                                                        FrameExport const& frame) {
    if (renderer.width() <= 0 || renderer.height() <= 0) return std::string("nothing to export: the viewport is 0x0");
    std::error_code ec;
    if (kInBrowser) {
        // The page's file system lives in memory, out of the user's reach: the frame is written
        // to a folder of its own there, zipped, and the zip offered as one download; then both go.
        fs::path const stage = "/tmp/gbuffer-lab-export";
        fs::remove_all(stage, ec);
        fs::path const folder = stage / exportFolderName(dir);
        fs::create_directories(folder, ec);
        if (ec) return "cannot create the folder " + folder.string() + ": " + ec.message();
        std::optional<std::string> err = exportFrame(renderer, frame, folder.string());
        fs::path const zip = stage / exportZipName(dir);
        if (!err) err = zipFolder(folder.string(), exportFolderName(dir), zip.string());
        if (!err && !offerDownload(zip.string())) err = "cannot offer " + zip.string() + " as a download";
        fs::remove_all(stage, ec);
        return err;
    }
    fs::create_directories(dir, ec);
    if (ec) return "cannot create the folder " + dir + ": " + ec.message();
    return exportFrame(renderer, frame, dir);
}

std::optional<std::string> SessionController::exportViewer(int viewer, bool raw, std::string const& path,
                                                           EditorState const& state, Renderer& renderer) {
    if (viewer < 0 || viewer >= int(state.gbuffer.viewers.size()))
        return "there is no viewer " + std::to_string(viewer);
    ViewerState const& v = state.gbuffer.viewers[std::size_t(viewer)];
    return raw ? exportViewerExr(renderer, v.kind, path) : exportViewerPng(renderer, v, state.camera, path);
}

void SessionController::endCleanly() {
    if (recovery_) recovery_->endRunCleanly(pid_);
}

}  // namespace gbl::ui
