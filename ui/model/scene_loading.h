// Loading glTF scenes in the editor: a worker thread parses and decodes, the render thread uploads.
#pragma once

#include "gltf/loader.h"
#include "model/editor_state.h"
#include "model/file_browser.h"
#include "model/gbuffer_opening.h"
#include "model/program_capture.h"
#include "scene/scene_data.h"

#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace gbl::ui {

// What the worker and the render thread share while one load runs. The worker writes the
// progress; the render thread reads it for the progress bar and sets `cancel`.
struct SceneLoadProgress {
    std::atomic<float> fraction{0.0f};
    std::atomic<bool> cancel{false};
    std::atomic<bool> held{false};  // the worker waits at holdAtStage (test hook)

    // Test hook: the worker stops at the first report of this stage until released or
    // cancelled, so a test can cancel at a known point however fast the machine is.
    std::string holdAtStage;  // fixed before the worker starts
    std::mutex mutex;         // guards stage, released
    std::condition_variable wake;
    std::string stage;  // the loader's stage names are short; a copy per report is cheap
    bool released = false;
};

// One load in flight. Destroying it cancels the load and waits for the worker.
struct SceneLoadJob {
    SceneLoadJob() = default;
    SceneLoadJob(SceneLoadJob const&) = delete;
    SceneLoadJob& operator=(SceneLoadJob const&) = delete;
    SceneLoadJob(SceneLoadJob&&) = default;
    SceneLoadJob& operator=(SceneLoadJob&&) = default;
    ~SceneLoadJob();

    std::string path;
    std::shared_ptr<SceneLoadProgress> progress;
    std::future<GltfLoadResult> result;
    std::chrono::steady_clock::time_point started;
};

enum class SceneLoadOutcome { None, Loaded, Failed, Cancelled };

// Everything about scene loading between frames. Not part of EditorState: it owns a thread
// and is not a value a session saves or an undo step restores.
// What a dropped .json file is, from its "format" field: a session or a lesson opens as one
// (dropped on the window, or chosen in the browser's picker, which hands files over as a drop);
// any other file (a G-buffer manifest, a glTF, ...) is Other.
enum class DroppedDocument { Other, Session, Lesson };
DroppedDocument droppedDocumentKind(std::string const& path);

// A folder given to the editor whole (in the browser: dropped on the page, or chosen with File >
// Open folder..., and written into its in-memory file system keeping the relative paths), so a glTF
// finds its buffers and textures in their subfolders: the scene file to open in it, the first
// .gltf or .glb by path when there are several. Without a scene, an imported G-buffer in it (a folder
// holding manifest.json, or a `render --out` folder with camera.json and lights.json: docs/import.md),
// the first such folder by path, opens as File > Open G-buffer would. `label` names the folder in the messages.
struct FolderScene {
    std::optional<std::string> scene;    // the path to open; nullopt: none (message says why)
    std::optional<std::string> gbuffer;  // else the G-buffer folder to open
    std::string message;                 // one line for the log: what opens, what else was there, or why nothing
};
FolderScene findFolderScene(std::string const& dir, std::string const& label);

struct SceneLoadingState {
    std::optional<SceneLoadJob> job;     // the load in progress, if any
    std::vector<std::string> requests;   // paths asked for (menu, dialog, recent, script), oldest first
    std::vector<std::string> dropped;    // files dropped onto the window since the last frame
    glm::vec4 openItemRect{0.0f};        // File > "Open scene..." while the menu is open (0 otherwise), frame log
    glm::vec4 openFolderItemRect{0.0f};  // File > "Open folder..." likewise (the browser build's only)
    std::string holdNextAtStage;         // test hook, applied to the next load that starts
    bool allowOutsideUris = false;       // --allow-outside-uris

    // File > Open scene… dialog and the recent list (most recent first).
    std::vector<std::string> recent;
    FileBrowserState browser;  // File > Open scene

    // File > Open G-buffer, and dropped manifests and folders (model/gbuffer_opening.h).
    GBufferOpenState gbuffer;
    // File > Capture a program… (model/program_capture.h): its manifest opens as the G-buffer.
    ProgramCaptureState capture;

    // The last finished load, for the error dialog and for tests.
    SceneLoadOutcome lastOutcome = SceneLoadOutcome::None;
    std::string lastError;
    bool errorDialogRequested = false;
    bool errorDialogDismissed = false;  // close the error dialog as its OK button does (scripts)
};

inline constexpr std::size_t kMaxRecentScenes = 8;

// Hands a scene to the GPU (the editor passes Renderer::setScene): nullopt on success, else why
// not. The model never sees the renderer itself, so its tests need no GL.
using SceneUploader = std::function<std::optional<std::string>(SceneData const&)>;

// Moves `path` to the front of the recent list, keeping at most kMaxRecentScenes entries.
void rememberRecentScene(SceneLoadingState& state, std::string const& path);

// Starts loading `path` on a worker thread. Refused (returns a sentence) while another load
// runs: the user cancels that one first, so two scenes never race to become current.
std::optional<std::string> startSceneLoad(SceneLoadingState& state, std::string const& path);

// Asks the running load to stop at its next progress report; a held worker is woken.
void cancelSceneLoad(SceneLoadingState& state);
// Lets a worker held by the test hook continue.
void releaseHeldLoad(SceneLoadingState& state);

bool sceneLoading(SceneLoadingState const& state);
// The stage last reported by the running load ("" when none runs) and its fraction.
std::string currentLoadStage(SceneLoadingState const& state);
float currentLoadFraction(SceneLoadingState const& state);
bool loadHeld(SceneLoadingState const& state);

// When the worker has finished, takes its result and clears the job; nullopt otherwise.
std::optional<GltfLoadResult> takeFinishedLoad(SceneLoadingState& state);

// Makes `scene` the editor's scene: uploads it (render thread) and resets what depends on it:
// lights (the file's, which the loader generates for a file without any; or the default rig),
// bounds, orbit centre, and a camera framing it. fromFile: a glTF scene (false: the procedural default scene). On
// failure the renderer and the state keep the previous scene and the error sentence is returned.
std::optional<std::string> installScene(SceneData const& scene, bool fromFile, int defaultLightCount,
                                        EditorState& state, SceneUploader const& upload);

// Render thread, once per frame: hands dropped G-buffers (folders, .json) to loading.gbuffer,
// starts requested loads (a drop opens its first scene file) and installs a finished one. Errors
// and cancellations are logged; errors also open the error dialog. Returns true when a new
// scene became current.
bool updateSceneLoading(SceneLoadingState& loading, int defaultLightCount, EditorState& state,
                        SceneUploader const& upload);

}  // namespace gbl::ui
