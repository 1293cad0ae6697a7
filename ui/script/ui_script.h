// UI test scripts: drive the real editor through the state its panels write, and check the
// result. One command per line, '#' starts a comment:
//
//   frames N                    run N frames before the next command
//   set KEY VALUE               mode|cull|blit|view|tonemap NAME, exposure F, cubes|wireframes|animate 0|1,
//                               time SECONDS (light animation), lights N (default scene lights)
//   light I FIELD VALUE         edit light I through the validated path the Lights panel uses;
//                               FIELD = x y z r g b intensity kc kl kq threshold
//   select I                    select light I (as a click in the list does)
//   click-light I               click the pixel where light I's cube is drawn (ray pick)
//   frame-scene                 the F key
//   inspect X Y                 lock the pixel inspector on viewport pixel (X, Y)
//   expect-breakdown-sums TOL   the inspector's per-light sum equals the stored lit value
//                               within TOL + 1% (16-bit float storage, CPU vs GPU float math)
//   resize W H                  resize the window (0 0 minimises the viewport)
//   capture NAME                keep the renderer's final image under NAME
//   screenshot FILE             write the whole window as PNG
//   measure N                   measure the editor's own cost over N frames and print it
//   expect-windows              every editor window exists, is visible and has a size
//   expect-different A B MIN    mean |A - B| per channel (0..1) at least MIN
//   expect-same A B MAX         mean |A - B| per channel at most MAX
//   expect-pixels-differ A B N  at least N pixels differ by more than one 8-bit step
//   expect-message TEXT         the Lights panel's refusal message contains TEXT
//   expect-no-message           ... and is empty
//   expect-selected I           light I is selected
//   expect-lights N             the list holds N lights
//   expect-no-gl-errors         the renderer counted no GL errors so far
//   expect-mode-used NAME       the last frame ran this lighting mode (no silent fallback)
//   expect-smaller A B          capture A is narrower and lower than capture B
//   expect-log TEXT             some log line contains TEXT
//   save-session FILE           File > Save as (expect-ok: the check fails when saving fails)
//   open-session FILE           File > Open; fails the check when the file is refused
//   open-bad-session FILE       File > Open of a file that must be refused (editor keeps its state)
//   undo / redo                 Ctrl+Z / Ctrl+Y
//   expect-recovery-offered     a previous run's autosave is offered (after an unclean exit)
//   recover                     accept that offer
//   wait-autosave SECONDS       run frames until the editor wrote its recovery autosave (fails after SECONDS)
//   expect-light I FIELD VALUE  light I's FIELD (as for `light`) equals VALUE
//   expect-setting KEY NAME     mode|cull|blit|view|tonemap is NAME
//   export-all DIR              File > Export all into DIR (the set `render --out` writes)
//   export-viewer NAME png|exr FILE  export a G-buffer viewer (position normal albedo specular depth)
//   expect-file PATH            a file exists and is not empty
//   wait SECONDS                run frames for SECONDS of wall-clock time
//   wait-log SECONDS TEXT       run frames until a log line contains TEXT (fails after SECONDS)
//   shader-break FILE           append a compile error to FILE in $GBL_SHADER_DIR (never the source tree)
//   shader-fix FILE             put FILE back as it was before shader-break
//   soak-baseline               remember the live GL object count and the process RSS
//   expect-soak-stable N MB     live GL objects within N of the baseline, RSS grown by at most MB
//   print TEXT
//
// Scene loading (ui/scene_loading.h; run by ui/ui_script_scene.cpp). Any word may use ${NAME}
// for an environment variable (ctest sets GBL_SHARED_GLTF_DIR and GBL_TEST_DATA_DIR); an unset
// one fails the script's load.
//   skip-unless-exists PATH     end the script as skipped ("ui-test SKIP") when PATH is absent
//   open-scene PATH             File > Open scene: starts loading on the worker
//   drop-files PATH...          the same files dropped onto the window
//   hold-load STAGE             the next load waits when it first reports STAGE ("decoding images")
//   wait-load-held              wait until the running load waits at that stage (60 s at most)
//   release-load                let a held load go on
//   cancel-load                 the Cancel button of the progress window
//   wait-scene-loaded           wait until no load runs and its result is applied (300 s at most)
//   expect-loading              a load is running
//   expect-load-stage TEXT      the running load's stage contains TEXT
//   expect-load-outcome WHAT    the last finished load: loaded | failed | cancelled
//   expect-load-error TEXT      ... and its error sentence contains TEXT
//   expect-scene TEXT           the current scene's source contains TEXT
//   expect-triangles N          the current scene has N triangles
//   expect-camera-frames-scene  the scene's bounds are in front of the camera and inside the view
//   expect-window-shown TITLE   an ImGui window (also a dialog) of that title was drawn this frame
//   dismiss-load-error          press OK in the load error dialog
#pragma once

#include "model/editor_state.h"
#include "renderer.h"
#include "model/scene_loading.h"
#include "script/screenshot.h"

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gbl::ui {

// What the script needs from the running editor beyond its state.
struct ScriptHost {
    EditorState& state;
    Renderer& renderer;
    SceneLoadingState* sceneLoading = nullptr;              // null: this editor cannot load scenes
    std::function<bool(std::string const&)> windowShown{};  // an ImGui window of that name was drawn
    std::function<RgbImage()> readWindow{};
    std::function<void(int, int)> resizeWindow{};
    std::function<std::string(EditorWindow)> windowProblem{};  // empty when the window is visible
    std::function<void(glm::ivec2)> clickViewport{};           // as a click on that viewport pixel
    std::function<void()> frameScene{};
    std::function<std::vector<PointLight>(int)> defaultLights{};  // empty function: not the default scene
    std::function<std::optional<std::string>(std::string const&)> openSession{};  // error sentence or nullopt
    std::function<std::optional<std::string>(std::string const&)> saveSession{};
    std::function<void()> undo{};
    std::function<void()> redo{};
    std::function<bool()> recoveryOffered{};
    std::function<void()> acceptRecovery{};
    std::function<int()> autosaves{};  // recovery autosaves written so far
    std::function<std::optional<std::string>(std::string const&)> exportAll{};
    std::function<std::optional<std::string>(int viewer, bool raw, std::string const& path)> exportViewer{};
};

class UiScript {
public:
    // Reads and checks the whole script up front, so a typo fails before the editor runs.
    static std::optional<UiScript> load(std::string const& path, std::string* error);

    // Runs commands until one waits for frames or the script ends. Call once per frame, after
    // the UI was drawn and before the buffers are swapped (captures read the back buffer).
    void step(ScriptHost& host);
    bool finished() const { return next_ >= commands_.size() && wait_ == 0 && !until_; }
    int failures() const { return failures_; }
    // A skip-unless-exists found its file missing: the script ended without checking anything.
    bool skipped() const { return skipped_; }

private:
    struct Command {
        int line = 0;
        std::vector<std::string> words;
    };
    void run(Command const& c, ScriptHost& host);
    void check(bool ok, Command const& c, std::string const& detail);

    std::string path_;
    std::vector<Command> commands_;
    std::size_t next_ = 0;
    int wait_ = 0;
    int failures_ = 0;
    std::map<std::string, FloatImage> captures_;
    // Scene-loading commands (ui/ui_script_scene.cpp).
    static int sceneCommandArity(std::string const& name);  // -2: not a scene command
    void runSceneCommand(Command const& c, ScriptHost& host);
    bool skipped_ = false;
    // A command that waits for a condition (wait-autosave): checked once per frame until it
    // holds or the deadline passes.
    std::function<bool()> until_;
    std::optional<Command> untilCommand_;
    double untilDeadline_ = 0.0;
    std::map<std::string, std::string> brokenShaders_;  // file -> original text
    long baselineObjects_ = -1;
    double baselineRssMb_ = 0.0;
};

}  // namespace gbl::ui
