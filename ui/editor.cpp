// The editor's window loop: GLFW window and GL context, ImGui set-up, the per-frame sequence
// (render, viewers, inspector, UI, present), screenshots and UI test scripts.
#include "editor.h"

#include "scene/default_scene.h"
#include "frame_export.h"
#include "model/editor_state.h"
#include "panels/layout.h"
#include "panels/panel_gbuffer.h"
#include "panels/panel_lights.h"
#include "panels/panel_log.h"
#include "panels/panel_pixel_inspector.h"
#include "panels/panel_stats.h"
#include "panels/panel_viewport.h"
#include "gl/caps.h"
#include "gltf/loader.h"
#include "gl/gpu_timer.h"
#include "model/image_range.h"
#include "panels/gui_compat.h"
#include "core/light_math.h"
#include "model/light_pick.h"
#include "panels/panel_pipeline.h"
#include "panels/panel_scene_loading.h"
#include "model/pixel_breakdown.h"
#include "renderer.h"
#include "gl/gpu_timer.h"
#include "model/scene_loading.h"
#include "script/screenshot.h"
#include "session_controller.h"
#include "script/ui_script.h"
#include "gpu/view_target.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#include <imgui_internal.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <thread>

#include <unistd.h>

namespace gbl {

namespace {

using ui::EditorState;
using ui::EditorWindow;
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// --- window and context --------------------------------------------------------------------

// GLFW reports errors through a C callback without a user pointer; the latest one is kept so
// start-up failures can say why in one sentence.
std::string gLastGlfwError;

void onGlfwError(int, char const* description) { gLastGlfwError = description ? description : "unknown error"; }

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

struct GlfwSession {
    GlfwSession() = default;
    GlfwSession(GlfwSession const&) = delete;
    GlfwSession& operator=(GlfwSession const&) = delete;
    ~GlfwSession() {
        if (window) glfwDestroyWindow(window);
        glfwTerminate();
    }
    GLFWwindow* window = nullptr;
};

// Parses "3.3" into (3, 3); empty means no limit.
bool parseGlLimit(std::string const& text, int& major, int& minor) {
    major = minor = 0;
    if (text.empty()) return true;
    return std::sscanf(text.c_str(), "%d.%d", &major, &minor) == 2 && major >= 3;
}

// --- GPU objects the editor owns (beside the renderer's) -----------------------------------

struct EditorGpu {
    std::array<ViewTarget, 5> viewTargets;  // one per G-buffer viewer
    std::array<std::optional<ViewParams>, 5> drawnParams;  // what each target last showed
    GpuTimer timer;                         // the editor's own GPU work, for the Stats window
};

bool sameView(ViewParams const& a, ViewParams const& b) {
    return a == b;
}

// --- scene set-up --------------------------------------------------------------------------

// Loads a glTF file (or builds the default scene when path is empty) on this thread and installs
// it (ui/model/scene_loading.h, installScene). Start-up and sessions use it; File > Open, drops and
// scripts load on a worker instead (updateSceneLoading). On failure the current scene and
// state stay as they were and an error sentence is returned.
std::optional<std::string> loadScene(std::optional<std::string> const& path, int defaultLightCount, bool allowOutsideUris,
                                     EditorState& state, Renderer& renderer) {
    auto const upload = [&renderer](SceneData const& scene) { return renderer.setScene(scene); };
    if (!path) return ui::installScene(makeDefaultScene({}), false, defaultLightCount, state, upload);
    GltfLoadOptions gltfOptions;
    gltfOptions.allowOutsideUris = allowOutsideUris;
    GltfLoadResult result = loadGltf(*path, gltfOptions);
    if (!result.scene) return result.error;
    return ui::installScene(*result.scene, true, defaultLightCount, state, upload);
}

// GLFW's drop callback has no closure: the window's user pointer is the loading state.
void onFilesDropped(GLFWwindow* window, int count, char const** paths) {
    auto* loading = static_cast<ui::SceneLoadingState*>(glfwGetWindowUserPointer(window));
    if (!loading) return;
    for (int i = 0; i < count; ++i) loading->dropped.emplace_back(paths[i]);
}

// --- per-frame pieces ----------------------------------------------------------------------

std::vector<PointLight> animatedLights(EditorState const& state) {
    std::vector<PointLight> lights = state.lights;
    if (state.animation.time != 0.0f) orbitLights(lights, state.orbitCenter, state.animation.time);
    return lights;
}

// Selects the light whose cube is under the pixel. With a depth step the cubes are hidden by
// walls, so only cubes in front of the surface at that pixel can be hit; without one they show
// through walls and are pickable through them too, as drawn.
void pickLightAt(EditorState& state, Renderer& renderer, std::span<PointLight const> drawn, glm::ivec2 pixel) {
    glm::vec2 const size(float(renderer.width()), float(renderer.height()));
    ui::Ray const ray = ui::cameraRay(state.camera, glm::vec2(pixel), size);
    float maxDistance = std::numeric_limits<float>::max();
    if (state.pipeline.depthCopy != DepthCopy::Off) {
        PixelSample const s = renderer.samplePixel(pixel.x, pixel.y, state.camera);
        // A little past the surface so a cube resting on it is still hit.
        if (s.covered) maxDistance = glm::length(glm::vec3(s.position) - state.camera.position) * 1.001f + 1e-3f;
    }
    int const hit = ui::pickLight(ray, drawn, renderer.lightCubeHalfSize(), maxDistance);
    if (hit >= 0) {
        state.lightsPanel.selected = hit;
        state.lightsPanel.message.clear();
    }
}

// The selected light's centre in the viewport image (0..1, top-left origin), when in front.
std::optional<glm::vec2> selectedLightInImage(EditorState const& state, std::span<PointLight const> drawn,
                                              Renderer const& renderer) {
    int const i = state.lightsPanel.selected;
    if (i < 0 || i >= int(drawn.size()) || renderer.width() <= 0 || renderer.height() <= 0) return std::nullopt;
    float const aspect = float(renderer.width()) / float(renderer.height());
    glm::vec4 const clip = state.camera.projection(aspect) * state.camera.view() * glm::vec4(drawn[std::size_t(i)].position, 1.0f);
    if (clip.w <= state.camera.nearPlane) return std::nullopt;
    glm::vec2 const ndc = glm::vec2(clip) / clip.w;
    return glm::vec2(ndc.x * 0.5f + 0.5f, 0.5f - ndc.y * 0.5f);
}

ui::CameraInput gatherCameraInput(GLFWwindow* window, EditorState const& state, float dt, bool keyboardFree) {
    ui::CameraInput in;
    in.orbitDrag = state.viewport.orbitDrag;
    in.lookDrag = state.viewport.lookDrag;
    in.panDrag = state.viewport.panDrag;
    in.dolly = state.viewport.wheel;
    in.dt = dt;
    in.viewportHeight = float(std::max(state.viewport.size.y, 1));
    // Keys fly the camera while the mouse is over the viewport or a drag started there, and
    // never while a text field has the keyboard.
    bool const flying = keyboardFree && (state.viewport.hovered || state.viewport.lookDrag != glm::vec2(0.0f));
    if (flying) {
        auto key = [&](int k) { return glfwGetKey(window, k) == GLFW_PRESS ? 1.0f : 0.0f; };
        in.move = glm::vec3(key(GLFW_KEY_D) - key(GLFW_KEY_A), key(GLFW_KEY_E) - key(GLFW_KEY_Q),
                            key(GLFW_KEY_W) - key(GLFW_KEY_S));
        in.fast = key(GLFW_KEY_LEFT_SHIFT) > 0.0f || key(GLFW_KEY_RIGHT_SHIFT) > 0.0f;
    }
    return in;
}

// Key presses (edges, not held keys) the editor reacts to outside ImGui widgets.
struct KeyEdges {
    bool wasDown[GLFW_KEY_LAST + 1] = {};
    bool pressed(GLFWwindow* window, int key) {
        bool const down = glfwGetKey(window, key) == GLFW_PRESS;
        bool const edge = down && !wasDown[key];
        wasDown[key] = down;
        return edge;
    }
};

std::string windowProblem(EditorWindow which) {
    ImGuiWindow const* w = ImGui::FindWindowByName(ui::windowName(which));
    if (!w) return "does not exist";
    if (!w->Active) return "was not drawn this frame";
    if (w->Hidden) return "is hidden";
    if (w->Collapsed) return "is collapsed";
    if (w->Size.x < 40.0f || w->Size.y < 40.0f) return "is too small to use";
    ImVec2 const display = ImGui::GetIO().DisplaySize;
    if (w->Pos.x < -1.0f || w->Pos.y < -1.0f || w->Pos.x + w->Size.x > display.x + 1.0f ||
        w->Pos.y + w->Size.y > display.y + 1.0f)
        return "extends past the window";
    return {};
}

// What the Edit menu asked for this frame.
struct EditRequest {
    bool undo = false;
    bool redo = false;
};

EditRequest drawMainMenu(EditorState& state, GlCaps const& caps, ui::SessionController& sessions,
                         ui::SceneLoadingState& loading) {
    EditRequest edit;
    if (!ImGui::BeginMainMenuBar()) return edit;
    if (ImGui::BeginMenu("File")) {
        ui::drawSceneMenuItems(loading);
        ImGui::Separator();
        ui::drawSessionMenuItems(sessions.panel);
        ImGui::Separator();
        if (ImGui::MenuItem("Quit")) state.quitRequested = true;
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        if (ImGui::MenuItem("Undo", "Ctrl+Z", false, sessions.history().canUndo())) edit.undo = true;
        if (ImGui::MenuItem("Redo", "Ctrl+Y", false, sessions.history().canRedo())) edit.redo = true;
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        if (ImGui::MenuItem("Reset layout", nullptr, false, ui::kHasDocking)) state.layout.resetRequested = true;
        if (!ui::kHasDocking && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip("this ImGui build has no docking: the windows are tiled and always in place");
        if (ImGui::MenuItem("Frame scene", "F")) ui::frameBounds(state.rig, state.camera, state.sceneBounds);
        ImGui::EndMenu();
    }
    // Status on the right: context and the newest log line.
    std::string status = caps.renderer + " | GL " + std::to_string(caps.major) + "." + std::to_string(caps.minor);
    if (!state.log.lines.empty()) status = state.log.lines.back() + "   " + status;
    float const width = ImGui::CalcTextSize(status.c_str()).x;
    float const x = ImGui::GetWindowWidth() - width - 12.0f;
    if (x > ImGui::GetCursorPosX()) {
        ImGui::SetCursorPosX(x);
        ImGui::TextDisabled("%s", status.c_str());
    }
    ImGui::EndMainMenuBar();
    return edit;
}

// Refits viewer ranges that asked for it (button) or are on auto (about once a second).
void fitViewerRanges(EditorState& state, Renderer& renderer, long frame) {
    for (auto& v : state.gbuffer.viewers) {
        // Auto-fit at the first frame with data, then about once a second (60 frames).
        bool const autoDue = v.autoFit && (v.lastFitFrame < 0 || frame - v.lastFitFrame >= 60);
        if (!v.fitRequested && !autoDue) continue;
        v.fitRequested = false;
        ui::ValueRange r;
        switch (v.kind) {
        case ui::ViewerKind::Position:
            r = ui::fitRange(renderer.readAttachment(Attachment::Position), v.channelMask & 0x7, ui::RangeSkip::ZeroAlpha);
            break;
        case ui::ViewerKind::Depth:
            r = ui::fitRange(renderer.readAttachment(Attachment::Depth), 0x1, ui::RangeSkip::FarDepth, v.linearDepth,
                             v.cameraClipPlanes ? state.camera.nearPlane : v.nearPlane,
                             v.cameraClipPlanes ? state.camera.farPlane : v.farPlane);
            break;
        case ui::ViewerKind::Albedo:
        case ui::ViewerKind::Specular: {
            unsigned const mask = v.kind == ui::ViewerKind::Specular ? 0x8u : (v.channelMask & 0x7);
            r = ui::fitRange(renderer.readAttachment(Attachment::AlbedoSpec), mask, ui::RangeSkip::None);
            break;
        }
        case ui::ViewerKind::Normal: continue;  // normals are shown as directions, not remapped
        }
        if (r.samples > 0) {
            v.rangeMin = r.min;
            v.rangeMax = r.max;
            v.lastFitFrame = frame;
        }
    }
}

void printMeasurement(ui::CostMeasurement const& m, glm::ivec2 window, glm::ivec2 viewport, int lights) {
    double const n = std::max(m.frames, 1);
    double const editor = (m.viewersMs + m.uiMs + m.imguiMs) / n;
    double const frame = m.frameMs / n;
    std::printf("editor cost over %d frames, window %dx%d, viewport %dx%d, %d lights:\n", m.frames, window.x, window.y,
                viewport.x, viewport.y, lights);
    std::printf("  renderer frame   %8.2f ms\n", m.renderMs / n);
    std::printf("  viewers          %8.2f ms  (view passes, range fits, pixel sample)\n", m.viewersMs / n);
    std::printf("  UI build         %8.2f ms  (all panels, CPU)\n", m.uiMs / n);
    std::printf("  ImGui draw       %8.2f ms\n", m.imguiMs / n);
    std::printf("  whole frame      %8.2f ms\n", frame);
    std::printf("  editor share     %8.1f %%  (viewers + UI build + ImGui draw) / whole frame\n",
                frame > 0.0 ? 100.0 * editor / frame : 0.0);
    std::fflush(stdout);
}

}  // namespace

int runEditor(EditorOptions const& options) {
    if (!displayAvailable()) {
        printNoDisplay("neither DISPLAY nor WAYLAND_DISPLAY is set");
        return 1;
    }
    int limitMajor = 0, limitMinor = 0;
    if (!parseGlLimit(options.glLimit, limitMajor, limitMinor)) {
        std::fprintf(stderr, "gbuffer-lab: --gl \"%s\" is not a version like 3.3 (at least 3.3).\n", options.glLimit.c_str());
        return 2;
    }
    if (options.width <= 0 || options.height <= 0) {
        std::fprintf(stderr, "gbuffer-lab: the window size must be at least 1x1 (got %dx%d).\n", options.width, options.height);
        return 2;
    }
    std::optional<ui::UiScript> script;
    if (options.uiTestScript) {
        std::string error;
        script = ui::UiScript::load(*options.uiTestScript, &error);
        if (!script) {
            std::fprintf(stderr, "gbuffer-lab: %s\n", error.c_str());
            return 2;
        }
    }

    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit()) {
        printNoDisplay(gLastGlfwError);
        return 1;
    }
    GlfwSession glfw;
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    // macOS only hands out core contexts that are forward-compatible.
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
    glfw.window = glfwCreateWindow(options.width, options.height, "gbuffer-lab", nullptr, nullptr);
    if (!glfw.window) {
        std::fprintf(stderr, "gbuffer-lab: could not open an OpenGL 3.3 core window: %s\n", gLastGlfwError.c_str());
        return 1;
    }
    GLFWwindow* window = glfw.window;
    glfwMakeContextCurrent(window);
    bool const unattended = options.screenshotPath || options.uiTestScript || options.frames > 0;
    glfwSwapInterval(options.vsync && !unattended ? 1 : 0);

    GlCaps const caps = detectGlCaps(limitMajor, limitMinor);
    EditorState state;
    std::unique_ptr<Renderer> renderer;
    try {
        renderer = std::make_unique<Renderer>(caps, 0, 0);
    } catch (std::exception const& e) {
        std::fprintf(stderr, "gbuffer-lab: the renderer could not start on %s (%s): %s\n", caps.renderer.c_str(),
                     caps.version.c_str(), e.what());
        return 1;
    }
    int const defaultLightCount = options.lightCount.value_or(32);
    if (auto error = loadScene(options.scenePath, defaultLightCount, options.allowOutsideUris, state, *renderer)) {
        std::fprintf(stderr, "gbuffer-lab: %s\n", error->c_str());
        return 2;
    }
    ui::SceneLoader const sceneLoader = [&](std::string const& scene, int lightCount) {
        std::optional<std::string> path;
        if (scene != "default") path = scene;
        return loadScene(path, lightCount, options.allowOutsideUris, state, *renderer);
    };
    // Crash recovery for interactive runs. Unattended runs (screenshots, UI tests) neither
    // offer nor leave autosaves unless a test asks for it with GBL_RECOVERY_DIR.
    std::optional<ui::RecoveryDir> recoveryDir;
    char const* recoveryEnv = std::getenv("GBL_RECOVERY_DIR");
    if (!unattended || (recoveryEnv && *recoveryEnv)) recoveryDir.emplace(ui::defaultRecoveryDir());
    ui::SessionController sessions(ui::steadyClock(), recoveryDir, long(::getpid()));
    sessions.start(state, defaultLightCount);
    if (options.sessionPath) {
        if (auto error = sessions.openSession(*options.sessionPath, state, sceneLoader)) {
            std::fprintf(stderr, "gbuffer-lab: %s\n", error->c_str());
            sessions.endCleanly();  // a refused file is a clean exit, not a crash to recover from
            return 2;
        }
    }
    for (LightingMode mode : {LightingMode::Volumes, LightingMode::Tiled})
        if (auto why = renderer->modeUnavailable(mode)) ui::logMessage(state.log, *why);
    // Scenes opened from the menu, by drag-and-drop or by scripts load on a worker thread.
    ui::SceneLoadingState loading;
    loading.allowOutsideUris = options.allowOutsideUris;
    if (options.scenePath) ui::rememberRecentScene(loading, *options.scenePath);
    glfwSetWindowUserPointer(window, &loading);
    glfwSetDropCallback(window, onFilesDropped);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    // Unattended runs must not depend on, or leave behind, a layout file.
    if (unattended) io.IniFilename = nullptr;
    ui::enableConfigFlags(io);
    ImGui::StyleColorsDark();
    ui::loadFonts();
    float xscale = 1.0f, yscale = 1.0f;
    glfwGetWindowContentScale(window, &xscale, &yscale);
    ui::applyContentScale(xscale);
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");

    EditorGpu gpu;
    KeyEdges keys;
    int exitCode = 0;
    long frame = 0;
    auto lastFrame = Clock::now();
    auto lastReload = Clock::now();
    int const screenshotFrames = options.frames > 0 ? options.frames : 5;

    ui::ScriptHost host{.state = state, .renderer = *renderer};
    host.sceneLoading = &loading;
    host.windowProblem = windowProblem;
    host.readWindow = [window] {
        int w = 0, h = 0;
        glfwGetFramebufferSize(window, &w, &h);
        return ui::readWindow(w, h);
    };
    host.resizeWindow = [window](int w, int h) { glfwSetWindowSize(window, std::max(w, 1), std::max(h, 1)); };
    std::vector<PointLight> drawn;
    host.clickViewport = [&](glm::ivec2 px) { pickLightAt(state, *renderer, drawn, px); };
    host.frameScene = [&] { ui::frameBounds(state.rig, state.camera, state.sceneBounds); };
    if (state.sceneSource == "default") host.defaultLights = [](int n) { return makeDefaultLights(n); };
    host.openSession = [&](std::string const& path) { return sessions.openSession(path, state, sceneLoader); };
    host.saveSession = [&](std::string const& path) { return sessions.saveSession(path, state); };
    host.undo = [&] { sessions.undo(state); };
    host.redo = [&] { sessions.redo(state); };
    host.recoveryOffered = [&] { return sessions.panel.recoveryOffer.has_value(); };
    host.autosaves = [&] { return sessions.autosaves(); };
    host.exportAll = [&](std::string const& dir) {
        return ui::SessionController::exportAll(
            dir, *renderer, FrameExport{state.camera, drawn, state.pipeline, state.stats.last, state.sceneTriangles, {}});
    };
    host.exportViewer = [&](int viewer, bool raw, std::string const& path) {
        return ui::SessionController::exportViewer(viewer, raw, path, state, *renderer);
    };
    host.acceptRecovery = [&] {
        if (auto error = sessions.restoreRecovery(state, sceneLoader)) ui::logMessage(state.log, *error, true);
    };
    host.windowShown = [](std::string const& name) {
        ImGuiWindow const* w = ImGui::FindWindowByName(name.c_str());
        return w && w->Active && !w->Hidden;
    };

    while (!glfwWindowShouldClose(window) && !state.quitRequested) {
        auto const frameStart = Clock::now();
        float const dt = float(std::chrono::duration<double>(frameStart - lastFrame).count());
        lastFrame = frameStart;
        glfwPollEvents();
        int fbWidth = 0, fbHeight = 0;
        glfwGetFramebufferSize(window, &fbWidth, &fbHeight);
        if ((fbWidth == 0 || fbHeight == 0) && !unattended) {
            // Minimised: nothing to draw into; wait instead of spinning.
            glfwWaitEventsTimeout(0.1);
            continue;
        }
        ++frame;
        bool const measuring = state.measurement.remaining > 0;
        auto finishIfMeasuring = [&] {
            if (measuring) glFinish();
        };

        // A finished load becomes the scene before this frame renders; requested ones start.
        if (ui::updateSceneLoading(loading, defaultLightCount, state,
                                   [&](SceneData const& scene) { return renderer->setScene(scene); })) sessions.sceneChanged(state);

        // --- the deferred frame, at the size the viewport had last frame --------------------
        if (state.viewport.size != glm::ivec2(renderer->width(), renderer->height()))
            renderer->resizeTargets(state.viewport.size.x, state.viewport.size.y);
        if (state.animation.enabled) state.animation.time += dt * state.animation.speed;
        drawn = animatedLights(state);
        finishIfMeasuring();
        auto t0 = Clock::now();
        FrameStats frameStats;
        if (renderer->width() > 0 && renderer->height() > 0)
            // Interactive frames take the previous frame's GPU timings instead of waiting for
            // this one's; a measurement waits anyway (glFinish), so it can have exact ones.
            frameStats = renderer->render(FrameInput{state.camera, drawn, state.pipeline, measuring});
        finishIfMeasuring();
        double const renderMs = msSince(t0);

        // --- viewers, range fits and the pixel inspector's sample ---------------------------
        t0 = Clock::now();
        gpu.timer.begin("viewers");
        std::array<unsigned, 5> viewerTextures{};
        if (renderer->width() > 0 && renderer->height() > 0 && state.gbuffer.visible) {
            ui::GBufferPanelState& gb = state.gbuffer;
            int const turn = gb.nextRefresh;
            gb.nextRefresh = (gb.nextRefresh + 1) % int(gb.viewers.size());
            for (std::size_t i = 0; i < gpu.viewTargets.size(); ++i) {
                ui::ViewerState const& v = gb.viewers[i];
                ViewParams const params = ui::viewerParams(v);
                ViewTarget& target = gpu.viewTargets[i];
                bool const stale = !target.texture || target.texture.width() != renderer->width() ||
                                   target.texture.height() != renderer->height() || !gpu.drawnParams[i] ||
                                   !sameView(*gpu.drawnParams[i], params);
                if (gb.refreshEveryFrame || int(i) == turn || stale) {
                    Camera clip = state.camera;
                    if (v.kind == ui::ViewerKind::Depth && !v.cameraClipPlanes) {
                        clip.nearPlane = v.nearPlane;
                        clip.farPlane = v.farPlane;
                    }
                    renderer->drawView(params, FrameInput{clip, drawn, state.pipeline}, target);
                    // Exact texels when zoomed in: the viewers are for reading values, not pictures.
                    target.texture.setFilter(GL_NEAREST, GL_NEAREST);
                    gpu.drawnParams[i] = params;
                }
                viewerTextures[i] = target.texture.id();
            }
            fitViewerRanges(state, *renderer, frame);
        }
        gpu.timer.end();
        ui::PixelInspectorState& inspector = state.inspector;
        if (inspector.pixel && inspector.pixel->x < renderer->width() && inspector.pixel->y < renderer->height()) {
            inspector.sample = renderer->samplePixel(inspector.pixel->x, inspector.pixel->y, state.camera);
            inspector.breakdown = ui::breakDownPixel(*inspector.sample, drawn, state.camera, state.pipeline);
            inspector.breakdownNote = inspector.breakdown ? "" : "background: no surface, no lights";
        } else {
            inspector.sample.reset();
            inspector.breakdown.reset();
            inspector.breakdownNote = "no pixel";
        }
        finishIfMeasuring();
        double const viewersMs = msSince(t0);

        // --- hot shader reload, about once a second ------------------------------------------
        if (std::chrono::duration<double>(Clock::now() - lastReload).count() >= 1.0) {
            lastReload = Clock::now();
            for (auto const& message : renderer->reloadChangedShaders()) {
                bool const failed = message.find("fail") != std::string::npos || message.find("error") != std::string::npos;
                ui::logMessage(state.log, message, failed);
            }
        }

        // --- the UI ----------------------------------------------------------------------------
        t0 = Clock::now();
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        EditRequest const edit = drawMainMenu(state, caps, sessions, loading);
        ui::beginLayout(state.layout);
        ui::drawLightsPanel(state.lightsPanel, state.lights, state.animation, state.sceneBounds);
        ui::drawPipelinePanel(state.pipeline, ui::modeReasons([&](LightingMode m) { return renderer->modeUnavailable(m); }));
        ui::drawViewportPanel(state.viewport, state.pipeline, renderer->texture(Attachment::Final),
                              {renderer->width(), renderer->height()}, selectedLightInImage(state, drawn, *renderer));
        ui::drawGBufferPanel(state.gbuffer, viewerTextures, {renderer->width(), renderer->height()});
        ui::drawPixelInspectorPanel(state.inspector);
        ui::drawStatsPanel(state.stats, caps, int(state.lights.size()));
        ui::drawLogPanel(state.log);
        ui::drawSceneLoadingUi(loading);

        // What the panels asked for.
        bool const keyboardFree = !io.WantTextInput;
        if (state.viewport.clickPixel) pickLightAt(state, *renderer, drawn, *state.viewport.clickPixel);
        if (state.gbuffer.showInViewport) state.pipeline.view = *state.gbuffer.showInViewport;
        if (inspector.selectLight >= 0) state.lightsPanel.selected = inspector.selectLight;
        if (!inspector.locked || !inspector.pixel) {
            if (state.viewport.hoverPixel) {
                inspector.pixel = state.viewport.hoverPixel;
                inspector.source = "viewport";
            } else if (state.gbuffer.hoverPixel) {
                inspector.pixel = state.gbuffer.hoverPixel;
                inspector.source = "G-buffer viewer";
            }
        }
        if (keyboardFree && keys.pressed(window, GLFW_KEY_L)) inspector.locked = !inspector.locked;
        bool const frameKey = keyboardFree && keys.pressed(window, GLFW_KEY_F);
        if (state.viewport.frameRequested || frameKey) ui::frameBounds(state.rig, state.camera, state.sceneBounds);
        ui::applyCameraInput(state.rig, state.camera, gatherCameraInput(window, state, dt, keyboardFree));

        // Sessions, exports, undo and crash recovery (ui/session_controller.h).
        ui::SessionRequest const request = ui::drawSessionDialogs(sessions.panel);
        if (request.kind != ui::SessionRequestKind::None) {
            FrameExport exported{state.camera, drawn, state.pipeline, frameStats, state.sceneTriangles, {}};
            sessions.handle(request, state, *renderer, exported, sceneLoader);
        }
        bool const ctrl = glfwGetKey(window, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS ||
                          glfwGetKey(window, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
        bool const zPressed = keys.pressed(window, GLFW_KEY_Z);
        bool const yPressed = keys.pressed(window, GLFW_KEY_Y);
        bool const sPressed = keys.pressed(window, GLFW_KEY_S);
        bool const oPressed = keys.pressed(window, GLFW_KEY_O);
        if (keyboardFree && ctrl && sPressed) sessions.panel.saveRequested = true;
        // Ctrl+O opens a session, Ctrl+Shift+O a scene.
        bool const shift = glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                           glfwGetKey(window, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
        if (keyboardFree && ctrl && shift && oPressed)
            ui::openSceneDialog(loading, loading.recent.empty() ? std::string() : loading.recent.front());
        if (keyboardFree && ctrl && !shift && oPressed)
            ui::openSessionDialog(sessions.panel, ui::SessionDialog::Open,
                                  sessions.panel.currentPath.empty() ? "session.json" : sessions.panel.currentPath);
        if (edit.undo || (keyboardFree && ctrl && zPressed)) sessions.undo(state);
        if (edit.redo || (keyboardFree && ctrl && yPressed)) sessions.redo(state);
        // A held slider is one edit: it becomes an undo step when released.
        sessions.afterFrame(state, ImGui::IsAnyItemActive());

        ImGui::Render();
        double const uiMs = msSince(t0);

        // --- present ---------------------------------------------------------------------------
        t0 = Clock::now();
        gpu.timer.begin("imgui");
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, fbWidth, fbHeight);
        glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        gpu.timer.end();
        finishIfMeasuring();
        double const imguiMs = msSince(t0);

        ui::EditorCost cost;
        cost.uiCpuMs = uiMs;
        for (auto const& [name, ms] : gpu.timer.finishFrame(false)) {
            if (name == "viewers") cost.viewersGpuMs = ms;
            if (name == "imgui") cost.imguiGpuMs = ms;
        }

        if (script) {
            script->step(host);
            if (script->finished()) state.quitRequested = true;
        }
        if (options.screenshotPath && frame == screenshotFrames) {
            if (auto error = ui::writePng(host.readWindow(), *options.screenshotPath)) {
                std::fprintf(stderr, "gbuffer-lab: %s\n", error->c_str());
                exitCode = 2;
            }
            state.quitRequested = true;
        }
        if (!options.screenshotPath && !script && options.frames > 0 && frame >= options.frames) state.quitRequested = true;

        glfwSwapBuffers(window);
        cost.frameCpuMs = msSince(frameStart);
        ui::recordFrame(state.stats, frameStats, cost);
        if (measuring) {
            ui::CostMeasurement& m = state.measurement;
            ++m.frames;
            m.renderMs += renderMs;
            m.viewersMs += viewersMs;
            m.uiMs += uiMs;
            m.imguiMs += imguiMs;
            m.frameMs += cost.frameCpuMs;
            if (--m.remaining == 0)
                printMeasurement(m, {fbWidth, fbHeight}, {renderer->width(), renderer->height()}, int(drawn.size()));
        }
    }

    // Stop a load still running (it ends at its next progress report) before the renderer goes.
    loading.job.reset();
    glfwSetWindowUserPointer(window, nullptr);

    if (script) {
        if (script->skipped()) {
            std::printf("ui-test: skipped\n");
        } else if (!script->finished()) {
            std::printf("ui-test FAIL: the window closed before the script ended\n");
            exitCode = 1;
        } else if (script->failures() > 0) {
            std::printf("ui-test: %d check(s) failed\n", script->failures());
            exitCode = 1;
        } else {
            std::printf("ui-test: all checks passed\n");
        }
    }

    sessions.endCleanly();

    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    // The renderer's GL objects go while the context is still current.
    gpu = EditorGpu{};
    renderer.reset();
    return exitCode;
}

}  // namespace gbl
