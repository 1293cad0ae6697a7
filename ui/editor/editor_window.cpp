// The editor's start and end: options, GLFW window and GL context, renderer, first scene and session,
// ImGui and its layout file, the UI test script's host, and the orderly shutdown.
#include "editor_loop.h"

#include "gl/gl_api.h"
#include "gltf/loader.h"
#include "model/browser_files.h"
#include "model/window_fit.h"
#include "panels/fonts.h"
#include "panels/gui_util.h"
#include "panels/panel_log.h"
#include "panels/panel_scene_loading.h"
#include "scene/default_scene.h"
#include "script/screenshot.h"
#include "session/config_dir.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#include <imgui_internal.h>
#include <implot.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include <unistd.h>

#ifdef __EMSCRIPTEN__
#include <emscripten/emscripten.h>
#endif

namespace gbl {

namespace {

// GLFW reports errors through a C callback without a user pointer; the latest one is kept so
// start-up failures can say why in one sentence.
std::string gLastGlfwError;

void onGlfwError(int, char const* description) {
    gLastGlfwError = description ? description : "unknown error";
}

bool displayAvailable() {
#if defined(__linux__) || defined(__FreeBSD__)
    char const* x11 = std::getenv("DISPLAY");
    char const* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
#else
    return true;
#endif
}

void printNoDisplay(std::string const& why) {
    std::fprintf(stderr,
                 "gbuffer-lab: no display (%s): the editor needs a window; use `gbuffer-lab render --out DIR` to "
                 "render without one, or run the editor under xvfb-run.\n",
                 why.c_str());
}

// Parses "3.3" into (3, 3); empty means no limit.
bool parseGlLimit(std::string const& text, int& major, int& minor) {
    major = minor = 0;
    if (text.empty()) return true;
    return std::sscanf(text.c_str(), "%d.%d", &major, &minor) == 2 && major >= 3;
}

// Loads a glTF file (or builds the default scene when path is empty, with its glass panes when
// `glass`) on this thread and installs it (ui/model/scene_loading.h, installScene). Start-up and sessions use it; File
// > Open, drops and scripts load on a worker instead (updateSceneLoading). On failure the current scene and state stay
// as they were and an error sentence is returned.
std::optional<std::string> loadScene(std::optional<std::string> const& path, int defaultLightCount, bool glass,
                                     EditorOptions const& options, ui::EditorState& state, Renderer& renderer) {
    auto const upload = [&renderer](SceneData const& scene) { return renderer.setScene(scene); };
    if (!path) {
        auto error = ui::installScene(makeDefaultScene({32, glass}), false, defaultLightCount, state, upload);
        if (!error) state.sceneGlass = glass;
        return error;
    }
    bool const allowOutsideUris = options.allowOutsideUris;
    GltfLoadOptions gltfOptions;
    gltfOptions.allowOutsideUris = allowOutsideUris;
    GltfLoadResult result = loadGltf(*path, gltfOptions);
    if (!result.scene) return result.error;
    return ui::installScene(*result.scene, true, defaultLightCount, state, upload);
}

// GLFW's drop callback has no closure: the window's user pointer is the editor.
void onFilesDropped(GLFWwindow* window, int count, char const** paths) {
    auto* editor = static_cast<Editor*>(glfwGetWindowUserPointer(window));
    if (!editor) return;
    for (int i = 0; i < count; ++i) editor->loading.dropped.emplace_back(paths[i]);
}

// The layout file in the user's config folder; empty (no layout file) when there is none to be had.
std::string layoutFilePath(ui::LogState& log) {
    std::optional<std::string> const dir = ui::configDir();
    std::string why;
    if (!dir)
        why = "neither XDG_CONFIG_HOME nor HOME names a folder";
    else if (auto error = ui::ensureConfigDir(*dir))
        why = *error;
    if (why.empty()) return ui::configFile(*dir, "imgui.ini");
    std::string const line = "window layout not saved: " + why;
    std::fprintf(stderr, "gbuffer-lab: %s\n", line.c_str());
    ui::logMessage(log, line, true);
    return {};
}

// Sets the UI scale's style and text size.
void setUiScale(Editor& editor, float scale) {
    editor.state.layout.scale.current = scale;
    ui::applyUiScale(editor.style.baseStyle, scale, editor.style.contentScale);
}

}  // namespace

void applyRequestedUiScale(Editor& editor) {
    ui::UiScaleState& scale = editor.state.layout.scale;
    if (!scale.requested) return;
    float const wanted = *scale.requested;
    scale.requested.reset();
    if (scale.saved != wanted) ImGui::MarkIniSettingsDirty();
    scale.saved = wanted;  // a choice from the menu is kept with the layout, --ui-scale or not
    if (wanted == scale.current) return;
    setUiScale(editor, wanted);
    ui::logMessage(editor.state.log, "UI scale " + ui::uiScaleText(wanted) + "x");
}

double msSince(EditorClock::time_point t0) {
    return std::chrono::duration<double, std::milli>(EditorClock::now() - t0).count();
}

std::optional<int> openWindow(Editor& editor) {
    EditorOptions const& options = editor.options;
    if (!displayAvailable()) {
        printNoDisplay("neither DISPLAY nor WAYLAND_DISPLAY is set");
        return 1;
    }
    int limitMajor = 0, limitMinor = 0;
    if (!parseGlLimit(options.glLimit, limitMajor, limitMinor)) {
        std::fprintf(stderr, "gbuffer-lab: --gl \"%s\" is not a version like 3.3 (at least 3.3).\n",
                     options.glLimit.c_str());
        return 2;
    }
    if (options.width <= 0 || options.height <= 0) {
        std::fprintf(stderr, "gbuffer-lab: the window size must be at least 1x1 (got %dx%d).\n", options.width,
                     options.height);
        return 2;
    }
    if (options.uiTestScript) {
        std::string error;
        editor.script = ui::UiScript::load(*options.uiTestScript, &error);
        if (!editor.script) {
            std::fprintf(stderr, "gbuffer-lab: %s\n", error.c_str());
            return 2;
        }
    }

    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit()) {
        printNoDisplay(gLastGlfwError);
        return 1;
    }
#ifdef __EMSCRIPTEN__
    // The browser: WebGL2 (OpenGL ES 3.0) in the page's canvas, whose size the page gives.
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    ui::WindowFit fit{options.width, options.height, false};
#else
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    // macOS only hands out core contexts that are forward-compatible.
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
    ui::WindowFit fit{options.width, options.height, false};
    if (!options.sizeGiven) {
        if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
            int areaX = 0, areaY = 0, areaWidth = 0, areaHeight = 0;
            float scaleX = 1.0f, scaleY = 1.0f;
            glfwGetMonitorWorkarea(monitor, &areaX, &areaY, &areaWidth, &areaHeight);
            glfwGetMonitorContentScale(monitor, &scaleX, &scaleY);
            fit =
                ui::fitWindowToWorkArea(options.width, options.height, areaWidth, areaHeight, std::max(scaleX, scaleY));
        }
        // A window manager then fits the reduced window, title bar included, to the screen.
        if (fit.reduced) glfwWindowHint(GLFW_MAXIMIZED, GLFW_TRUE);
    }
#endif
    editor.glfw.window = glfwCreateWindow(fit.width, fit.height, "gbuffer-lab", nullptr, nullptr);
    if (!editor.glfw.window) {
        std::fprintf(stderr, "gbuffer-lab: could not open an OpenGL 3.3 core window: %s\n", gLastGlfwError.c_str());
        return 1;
    }
    glfwMakeContextCurrent(editor.window());
#ifdef __EMSCRIPTEN__
    // The G-buffer's float attachments are drawn into only with this extension (most browsers have it).
    if (!gl::hasExtension("GL_EXT_color_buffer_float")) {
        std::fprintf(stderr,
                     "gbuffer-lab: this browser's WebGL2 has no EXT_color_buffer_float, so the G-buffer's float "
                     "attachments cannot be drawn into; try another browser or one with hardware acceleration on\n");
        return 1;
    }
#endif
    editor.unattended = options.screenshotPath || options.uiTestScript || options.frames > 0;
    glfwSwapInterval(options.vsync && !editor.unattended ? 1 : 0);
    editor.caps = detectGlCaps(limitMajor, limitMinor);
    return std::nullopt;
}

std::optional<int> startEditor(Editor& editor) {
    EditorOptions const& options = editor.options;
    ui::EditorState& state = editor.state;
    try {
        editor.renderer = std::make_unique<Renderer>(editor.caps, 0, 0);
    } catch (std::exception const& e) {
        std::fprintf(stderr, "gbuffer-lab: the renderer could not start on %s (%s): %s\n", editor.caps.renderer.c_str(),
                     editor.caps.version.c_str(), e.what());
        return 1;
    }
    editor.defaultLightCount = options.lightCount.value_or(32);
    if (auto error =
            loadScene(options.scenePath, editor.defaultLightCount, options.glass, options, state, *editor.renderer)) {
        std::fprintf(stderr, "gbuffer-lab: %s\n", error->c_str());
        return 2;
    }
    rememberHomeView(editor);
    // "default" is the default scene; "default+glass" (ui::kDefaultSceneGlass) stands its glass panes,
    // as --glass, a session with default_scene_glass and a lesson step with "scene": {"glass": true} ask.
    editor.sceneLoader = [&editor](std::string const& scene, int lightCount) {
        std::optional<std::string> path;
        bool const glass = scene == ui::kDefaultSceneGlass;
        if (scene != "default" && scene != ui::kDefaultSceneGlass) path = scene;
        auto error = loadScene(path, lightCount, glass, editor.options, editor.state, *editor.renderer);
        if (!error) rememberHomeView(editor);
        return error;
    };
    // Crash recovery for interactive runs. Unattended runs (screenshots, UI tests) neither
    // offer nor leave autosaves unless a test asks for it with GBL_RECOVERY_DIR.
    std::optional<ui::RecoveryDir> recoveryDir;
    char const* recoveryEnv = std::getenv("GBL_RECOVERY_DIR");
    if (!editor.unattended || (recoveryEnv && *recoveryEnv)) recoveryDir.emplace(ui::defaultRecoveryDir());
    ui::SessionController& sessions = editor.sessions.emplace(ui::steadyClock(), recoveryDir, ui::editorRunId());
    // With a G-buffer open, a session still stores the scene behind it.
    sessions.setSceneBehind(
        [&gbuffer = editor.loading.gbuffer](ui::EditorState const& s) -> std::optional<ui::EditorState> {
            if (!ui::gbufferOpen(gbuffer)) return std::nullopt;
            return ui::sceneBehind(s, gbuffer);
        });
    sessions.start(state, editor.defaultLightCount);
    if (options.sessionPath) {
        if (auto error = sessions.openSession(*options.sessionPath, state, editor.sceneLoader)) {
            std::fprintf(stderr, "gbuffer-lab: %s\n", error->c_str());
            sessions.endCleanly();  // a refused file is a clean exit, not a crash to recover from
            return 2;
        }
    }
    // What this context cannot run. Natively a line each in the log (volumes and tiled: asking
    // builds a mode's programs, and clustered waits until it is chosen); in the browser, where no
    // compute mode builds, the menu bar keeps the scene's line and Help > About this browser lists
    // them with the page's other limits.
    for (LightingMode mode :
         {LightingMode::Volumes, LightingMode::Tiled, LightingMode::Clustered, LightingMode::ForwardPlus}) {
        if (!ui::kInBrowser && (mode == LightingMode::Clustered || mode == LightingMode::ForwardPlus)) continue;
        std::optional<std::string> const why = editor.renderer->modeUnavailable(mode);
        if (!why) continue;
        if (!ui::kInBrowser) {
            ui::logMessage(state.log, *why);
            continue;
        }
        editor.browserAbout.contextLimits.push_back(*why);
        std::fprintf(stderr, "gbuffer-lab: %s\n", why->c_str());
    }
    if (options.logFramesPath) {
        if (auto error = editor.frameLog.open(*options.logFramesPath)) {
            std::fprintf(stderr, "gbuffer-lab: %s\n", error->c_str());
            sessions.endCleanly();
            return 2;
        }
    }
    if (options.gbufferPath) {
        // --gbuffer: the G-buffer over the scene, as File > Open G-buffer opens it; refused as a
        // bad --session is, one sentence and exit code 2.
        ui::GBufferRead const read = ui::readGBuffer(*options.gbufferPath);
        Renderer& renderer = *editor.renderer;
        if (auto error = ui::installGBuffer(editor.loading.gbuffer, *options.gbufferPath, read, state,
                                            [&](ImportedFrame const& f) { return renderer.setImportedGBuffer(f); })) {
            std::fprintf(stderr, "gbuffer-lab: %s\n", error->c_str());
            sessions.endCleanly();
            return 2;
        }
        ++editor.sceneGeneration;
        sessions.sceneChanged(state);
    }
    editor.render.continuous = options.continuousRender;
    // Scenes opened from the menu, by drag-and-drop or by scripts load on a worker thread.
    editor.loading.allowOutsideUris = options.allowOutsideUris;
    if (options.scenePath) ui::rememberRecentScene(editor.loading, *options.scenePath);
    glfwSetWindowUserPointer(editor.window(), &editor);
    glfwSetDropCallback(editor.window(), onFilesDropped);
    return std::nullopt;
}

void initImGui(Editor& editor) {
    EditorOptions const& options = editor.options;
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImPlot::CreateContext();  // the attenuation plot and the Stats window's timing history
    ImGuiIO& io = ImGui::GetIO();
    // Unattended runs must not depend on, or leave behind, a layout file; interactive ones keep
    // it in the config folder, not in whatever directory the editor was started from.
    if (!editor.unattended) editor.style.iniPath = layoutFilePath(editor.state.log);
    io.IniFilename = editor.style.iniPath.empty() ? nullptr : editor.style.iniPath.c_str();
    ui::enableConfigFlags(io);
    ImGui::StyleColorsDark();
    editor.style.baseStyle = ImGui::GetStyle();
    // The UI scale: --ui-scale (checked in runEditor), else the one kept with the layout, else 1.
    // The layout file is read now, not at the first frame, so the first frame has the right font.
    ui::UiScaleState& scale = editor.state.layout.scale;
    if (options.uiScale) {
        scale.current = ui::parseUiScale(*options.uiScale, "--ui-scale").value_or(1.0f);
        scale.fromCommandLine = true;
    }
    addViewSettingsHandler(editor);
    if (io.IniFilename) ImGui::LoadIniSettingsFromDisk(io.IniFilename);
    float xscale = 1.0f;
#ifndef __EMSCRIPTEN__  // Emscripten's GLFW (3.2) has no content scale; the page's canvas is in CSS pixels
    float yscale = 1.0f;
    glfwGetWindowContentScale(editor.window(), &xscale, &yscale);
#endif
    editor.style.contentScale = xscale > 0.0f ? xscale : 1.0f;
    if (auto warning = ui::loadUiFont(ui::uiFontPath())) {
        std::fprintf(stderr, "gbuffer-lab: %s\n", warning->c_str());
        ui::logMessage(editor.state.log, *warning, true);
    }
    setUiScale(editor, scale.current);
    // ImGui's backend installs no callbacks: the editor's own queue every event and feed ImGui
    // at a pace it can follow (editor_input.h).
    ImGui_ImplGlfw_InitForOpenGL(editor.window(), false);
#ifdef __EMSCRIPTEN__
    ImGui_ImplOpenGL3_Init("#version 300 es");
#else
    ImGui_ImplOpenGL3_Init("#version 330 core");
#endif
    installInputCallbacks(editor.window(), editor.input);
}

void rememberHomeView(Editor& editor) {
    // installScene has just placed the camera where the scene suggests (or framed it).
    editor.home = ui::CameraView{editor.state.camera, editor.state.rig};
    ++editor.sceneGeneration;
}

void connectScriptHost(Editor& editor) {
    ui::EditorState& state = editor.state;
    ui::SessionController& sessions = *editor.sessions;
    ui::ScriptHost& host = editor.host.emplace(ui::ScriptHost{.state = state, .renderer = *editor.renderer});
    GLFWwindow* window = editor.window();
    host.sceneLoading = &editor.loading;
    host.windowProblem = windowProblem;
    host.readWindow = [window] {
        int w = 0, h = 0;
        glfwGetFramebufferSize(window, &w, &h);
        return ui::readWindow(w, h);
    };
    host.resizeWindow = [window](int w, int h) { glfwSetWindowSize(window, std::max(w, 1), std::max(h, 1)); };
    host.clickViewport = [&editor](glm::ivec2 px) { pickLightAt(editor.state, *editor.renderer, editor.drawn, px); };
    host.frameScene = [&state] { ui::frameBounds(state.rig, state.camera, state.sceneBounds); };
    if (state.sceneSource == "default") host.defaultLights = [](int n) { return makeDefaultLights(n); };
    host.openSession = [&editor](std::string const& path) {
        return editor.sessions->openSession(path, editor.state, editor.sceneLoader);
    };
    host.saveSession = [&sessions, &state](std::string const& path) { return sessions.saveSession(path, state); };
    host.undo = [&sessions, &state] { sessions.undo(state); };
    host.redo = [&sessions, &state] { sessions.redo(state); };
    host.recoveryOffered = [&sessions] { return sessions.panel.recoveryOffer.has_value(); };
    host.autosaves = [&sessions] { return sessions.autosaves(); };
    host.exportAll = [&editor](std::string const& dir) {
        ui::EditorState const& s = editor.state;
        return ui::SessionController::exportAll(
            dir, *editor.renderer, FrameExport{s.camera, editor.drawn, s.pipeline, s.stats.last, s.sceneTriangles, {}});
    };
    host.exportViewer = [&editor](int viewer, bool raw, std::string const& path) {
        return ui::SessionController::exportViewer(viewer, raw, path, editor.state, *editor.renderer);
    };
    host.acceptRecovery = [&editor] {
        if (auto error = editor.sessions->restoreRecovery(editor.state, editor.sceneLoader))
            ui::logMessage(editor.state.log, *error, true);
    };
    host.windowShown = [](std::string const& name) {
        ImGuiWindow const* w = ImGui::FindWindowByName(name.c_str());
        return w && w->Active && !w->Hidden;
    };
}

int shutdownEditor(Editor& editor) {
    // Stop a load still running (it ends at its next progress report) before the renderer goes.
    editor.loading.job.reset();
    glfwSetWindowUserPointer(editor.window(), nullptr);

    if (editor.script) {
        ui::UiScript const& script = *editor.script;
        if (script.skipped()) {
            std::printf("ui-test: skipped\n");
        } else if (!script.finished()) {
            std::printf("ui-test FAIL: the window closed before the script ended\n");
            editor.exitCode = 1;
        } else if (script.failures() > 0) {
            std::printf("ui-test: %d check(s) failed\n", script.failures());
            editor.exitCode = 1;
        } else {
            std::printf("ui-test: all checks passed\n");
        }
    }

    editor.sessions->endCleanly();

    removeInputCallbacks(editor.window());
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImPlot::DestroyContext();
    ImGui::DestroyContext();
    // The renderer's GL objects go while the context is still current.
    editor.gpu = EditorGpu{};
    editor.renderer.reset();
    return editor.exitCode;
}

}  // namespace gbl

#ifdef __EMSCRIPTEN__
// A folder the page wrote into its file system (app/web/pre.js: dropped on the page, or chosen with
// File > Open folder...): its scene goes into the queue GLFW's drop callback feeds, so it opens as
// a dropped file does, with its buffers and textures found in their subfolders. `label` names the
// folder for the log; `unread` lists the files the page could not read ("" when none).
extern "C" EMSCRIPTEN_KEEPALIVE void gbl_open_folder(char const* dir, char const* label, char const* unread) {
    GLFWwindow* window = glfwGetCurrentContext();
    auto* editor = window ? static_cast<gbl::Editor*>(glfwGetWindowUserPointer(window)) : nullptr;
    if (!editor) {
        std::fprintf(stderr, "gbuffer-lab: the editor is not running; %s is not opened\n", label);
        return;
    }
    gbl::ui::LogState& log = editor->state.log;
    if (*unread) gbl::ui::logMessage(log, std::string(label) + ": these files could not be read: " + unread, true);
    gbl::ui::FolderScene const found = gbl::ui::findFolderScene(dir, label);
    gbl::ui::logMessage(log, found.message, !found.scene && !found.gbuffer);
    if (found.scene) editor->loading.dropped.push_back(*found.scene);
    // An imported G-buffer's folder (manifest and EXR files, or a `render --out` folder): as File > Open G-buffer.
    if (found.gbuffer) editor->loading.gbuffer.requests.push_back(*found.gbuffer);
}
#endif
