// UI test scripts: drive the real editor through the state its panels write, and check the
// result. One command per line, '#' starts a comment; any word may use ${NAME} for an environment
// variable (ctest sets GBL_SHARED_GLTF_DIR and GBL_TEST_DATA_DIR), and an unset one fails the
// script's load. The commands and their help are one table (ui/script/script_run.h):
// uiScriptHelp() prints it, and a script with an unknown command shows it.
#pragma once

#include "model/editor_state.h"
#include "model/scene_loading.h"
#include "renderer.h"
#include "script/screenshot.h"

#include <functional>
#include <memory>
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

struct ScriptRun;

class UiScript {
public:
    // Reads and checks the whole script up front, so a typo fails before the editor runs.
    static std::optional<UiScript> load(std::string const& path, std::string* error);

    UiScript(UiScript&&) noexcept;
    UiScript& operator=(UiScript&&) noexcept;
    ~UiScript();

    // Runs commands until one waits for frames or the script ends. Call once per frame, after
    // the UI was drawn and before the buffers are swapped (captures read the back buffer).
    void step(ScriptHost& host);
    bool finished() const;
    int failures() const;
    // A skip-unless-exists found its file missing: the script ended without checking anything.
    bool skipped() const;

private:
    UiScript();
    std::unique_ptr<ScriptRun> run_;
};

// Every command with its arguments and what it does, one per line (from the command table).
std::string uiScriptHelp();

}  // namespace gbl::ui
