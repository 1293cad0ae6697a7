// What the editor's main-loop steps share, and the steps themselves (runEditor in editor.cpp calls them in order).
#pragma once

#include "ab_frame.h"
#include "editor.h"
#include "editor_input.h"
#include "gl/caps.h"
#include "gl/gpu_timer.h"
#include "gpu/view_target.h"
#include "model/camera_views.h"
#include "model/discard_guard.h"
#include "model/editor_state.h"
#include "model/file_browser.h"
#include "model/frame_log.h"
#include "model/lesson_progress.h"
#include "model/lesson_state.h"
#include "model/render_inputs.h"
#include "model/scene_loading.h"
#include "msaa_views_service.h"
#include "panels/panel_browser_about.h"
#include "panels/panel_glossary.h"
#include "panels/panel_pipeline.h"
#include "renderer.h"
#include "script/ui_script.h"
#include "session/lesson_file.h"
#include "session_controller.h"
#include "viewer_tools_service.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace gbl {

using EditorClock = std::chrono::steady_clock;

double msSince(EditorClock::time_point t0);

// GPU objects the editor owns beside the renderer's.
struct EditorGpu {
    std::array<ViewTarget, 5> viewTargets;                 // one per G-buffer viewer
    ui::ViewerToolsGpu viewerTools;                        // diff heat maps of the viewer tools
    std::array<std::optional<ViewParams>, 5> drawnParams;  // what each target last showed
    // Which rendered frame each target shows (framesRendered when drawn): after a new frame the
    // viewers catch up one a frame, so a frame that is the last for a while (a scene just loaded,
    // then nothing changes) still reaches all five.
    std::array<std::uint64_t, 5> drawnFrame{};
    std::uint64_t framesRendered = 0;
    GpuTimer timer;         // the editor's own GPU work, for the Stats window
    ui::AbGpu ab;           // side B and the A/B diff (ab_frame.h)
    ui::MsaaViewsGpu msaa;  // the complex-pixel overlay and the samples heat map (msaa_views_service.h)
};

// The GLFW library and the editor's window; terminates GLFW when it goes.
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

// What the Edit menu asked for this frame.
struct EditRequest {
    bool undo = false;
    bool redo = false;
    bool quit = false;
    bool newSession = false;
    bool frameSelection = false;
    bool homeView = false;
};

// Wall-clock times of one frame's parts, for the editor cost measurement.
struct FrameTimes {
    EditorClock::time_point start;
    bool measuring = false;  // a measurement waits for the GPU (glFinish) at each boundary
    double renderMs = 0.0;
    double viewersMs = 0.0;
    double uiMs = 0.0;
    double imguiMs = 0.0;
    FrameStats frameStats;
    ui::EditorCost cost;  // the editor's own CPU and GPU costs, for the Stats window
    std::array<unsigned, 5> viewerTextures{};
    unsigned litDiffTexture = 0;             // the viewport's lit-frame diff heat map while shown, else 0
    unsigned viewportToolsTexture = 0;       // the viewport's attachment as its viewer tools show it, else 0
    std::vector<unsigned> overviewTextures;  // the attachment overview's cells while it is on
    int fbWidth = 0;
    int fbHeight = 0;
    float dt = 0.0f;
    bool rendered = false;  // the renderer ran this frame (render on change)
};

// Everything the steps share. Members are torn down in reverse order: the load job before the
// sessions, those before the renderer, the renderer while GLFW's context is still current.
struct Editor {
    explicit Editor(EditorOptions const& options) : options(options) {}

    EditorOptions const options;  // a copy: in the browser the editor outlives main's locals
    bool idle = false;            // the last frame rendered nothing and took no input (present())
    // The browser's page shows a loading line until the first complete frame (editor.cpp,
    // showPageWhenComplete): -1 until the scene first rendered, then the frames left, 0 once shown.
    int pageFramesLeft = -1;
    GlfwSession glfw;
    GlCaps caps;
    bool unattended = false;  // screenshots, UI tests, frame counts: no vsync, layout file or recovery
    int defaultLightCount = 32;

    std::optional<ui::UiScript> script;
    ui::EditorState state;
    std::unique_ptr<Renderer> renderer;
    ui::SceneLoader sceneLoader;
    std::optional<ui::SessionController> sessions;
    ui::SceneLoadingState loading;
    std::optional<ui::ScriptHost> host;

    EditorGpu gpu;
    EditorInput input;                       // GLFW's events, queued (editor_input.h)
    ui::FrameActions actions;                // this frame's shortcuts and fly keys
    std::vector<std::string> actionLog;      // what the editor did this frame, for --log-frames
    ui::RenderOnChange render;               // what the frame on screen was rendered from
    std::string renderReason;                // what changed, for the Stats window
    std::uint64_t sceneGeneration = 1;       // counts scenes handed to the renderer
    ui::CameraView home;                     // the scene's view (Home)
    bool showShortcuts = false;              // Help > Shortcuts
    ui::BrowserAboutState browserAbout;      // Help > About this browser (the browser build's)
    std::string menuStatus;                  // the menu bar's status as last drawn, for --log-frames
    ui::DiscardGuard discard;                // Quit / New / Open over unsaved edits
    ui::FrameLog frameLog;                   // --log-frames
    ui::PipelinePanelRects pipelineRects;    // where the Pipeline window drew its layout combo (--log-frames)
    std::vector<PointLight> drawn;           // this frame's lights (animated)
    ui::GlossaryWindowState glossaryWindow;  // the Glossary window (the lessons and the Help menu open it)
    // File > "Save window as PNG" (the browser build's: the page's files live in memory, so the
    // PNG is offered as a download). Frames until present() reads the window, so the closed menu
    // is not in the picture; 0 = none asked for. The item's rectangle is for the frame log.
    struct WindowShot {
        int framesLeft = 0;
        glm::vec4 itemRect{0.0f};
    } windowShot;

    // Fields one file alone uses, grouped under that file's name.
    // editor_window.cpp: the layout file and the style the UI scale starts from.
    struct WindowStyle {
        std::string iniPath;        // imgui.ini in the user's config folder; ImGui keeps a pointer to it
        ImGuiStyle baseStyle;       // the style at UI scale 1, which each scale change scales afresh
        float contentScale = 1.0f;  // the monitor's content scale (1 under Xvfb)
    } style;
    // editor_frame.cpp: what the frame loop remembers between frames.
    struct FrameMemory {
        std::uint64_t shaderGeneration = 0;      // counts shader reloads
        std::optional<glm::ivec2> sampledPixel;  // the inspector's pixel at its last sample
        // The mode and light count last checked for a long frame, and the ones it switched away
        // from (avoidLongFrame).
        std::optional<std::pair<LightingMode, std::size_t>> longFrameChecked;
        std::optional<std::pair<LightingMode, std::size_t>> longFrameSwitchedFrom;
        EditorClock::time_point lastFrame = EditorClock::now();
        EditorClock::time_point lastReload = EditorClock::now();
        std::pair<int, int> markedStep{-1, -1};  // the lesson and step the viewport's mark was measured for
    } frameMemory;
    // editor_requests.cpp: requests held while the unsaved-edits question (discard) is open.
    struct HeldRequests {
        std::vector<std::string> scenes;  // scene opens waiting for that answer
        std::optional<ui::SessionRequest> session;
        bool release = false;  // the answer was Discard: let the held requests through
    } held;
    // editor_lessons.cpp: the lessons, the glossary and the course progress.
    struct Course {
        ui::LessonState lessons;
        ui::LessonLibrary library;  // read from assets/lessons on the first frame
        bool loaded = false;
        ui::FileBrowserState browser;
        ui::Glossary glossary;  // assets/glossary.json, read with the lessons
        // The course progress (model/lesson_progress.h), read with the lessons from the config
        // folder and written there whenever it changes; no path = not kept (no config folder). A
        // file that could not be read is moved aside to .broken before the first write over it.
        ui::CourseProgress progress;
        std::string progressPath;
        bool progressBroken = false;
    } course;
    long frame = 0;
    int exitCode = 0;

    GLFWwindow* window() const { return glfw.window; }
};

// --- window and start-up (editor_window.cpp) -------------------------------------------------

// Checks the options, loads the test script and opens the window with a GL 3.3 core context;
// nullopt on success, else the exit code.
std::optional<int> openWindow(Editor& editor);
// Starts the renderer, loads the first scene and session, sets up crash recovery; nullopt or the exit code.
std::optional<int> startEditor(Editor& editor);
// Creates the ImGui context and backends; imgui.ini goes to the user's config folder.
void initImGui(Editor& editor);
// Applies a UI scale asked for during the last frame (View > UI scale): style, font atlas and the
// backend's font texture. Called before the frame's ImGui::NewFrame.
void applyRequestedUiScale(Editor& editor);
// Registers the editor's section of imgui.ini ("[gbuffer-lab][View]": UiScale=, LayoutScale=) with
// ImGui, read before the first frame and written with the layout (editor_view_settings.cpp).
void addViewSettingsHandler(Editor& editor);
// Answers the UI test script's questions about this editor (ui/script/ui_script.h, ScriptHost).
void connectScriptHost(Editor& editor);
// Reports the script's outcome, ends the session cleanly and releases ImGui and GL objects; the exit code.
int shutdownEditor(Editor& editor);

// --- the frame (editor_frame.cpp) -------------------------------------------------------------

// Polls events and starts the frame's clock; false when the window is minimised (skip the frame).
bool beginFrame(Editor& editor, FrameTimes& times);
// Finished scene loads, the deferred frame at the viewport's size, the viewers and the inspector's sample.
void renderScene(Editor& editor, FrameTimes& times);
// Picks shaders changed on disk, about once a second.
void reloadShaders(Editor& editor);
// Clears the window and draws ImGui's lists, runs the script, takes the screenshot and swaps.
void present(Editor& editor, FrameTimes& times);
// The Stats window's numbers and the cost measurement (printed when it completes).
void recordFrame(Editor& editor, FrameTimes const& times);

// The light whose cube is under the viewport pixel, or -1.
int lightAtPixel(ui::EditorState const& state, Renderer& renderer, std::span<PointLight const> drawn, glm::ivec2 pixel);
// Selects the light whose cube is under the viewport pixel.
void pickLightAt(ui::EditorState& state, Renderer& renderer, std::span<PointLight const> drawn, glm::ivec2 pixel);
// Writes this frame's --log-frames line (editor_log.cpp).
void logFrame(Editor& editor, FrameTimes const& times, double frameMs);
// Remembers the camera a newly installed scene starts with, for Home.
void rememberHomeView(Editor& editor);

// --- the UI (editor_panels.cpp, editor_requests.cpp) ------------------------------------------

// Starts the ImGui frame and draws the menu bar and every panel; returns what the Edit menu asked for.
EditRequest drawPanels(Editor& editor, FrameTimes const& times);
// What the panels asked for and the shortcuts: picking, inspector, camera, sessions, undo.
void handleRequests(Editor& editor, FrameTimes const& times, EditRequest const& edit);
// Closes an open imported G-buffer, giving back the scene's camera and lights: a session opened,
// restored or started afresh, or a lesson started, brings its own scene and lands on the scene's state.
void closeImportedGBuffer(Editor& editor);
// The Lessons window and what it asked for (ui/editor_lessons.cpp).
void drawLessons(Editor& editor);
// The viewport's lesson mark: a step whose claim has `mark` measures it on the editor's frame
// after each new frame (model/lesson_claims.h, claimMark); any other state clears it.
void markLessonClaim(Editor& editor, bool rendered);
// The lesson shown and the Lessons window's buttons, for --log-frames.
void lessonLogFields(Editor const& editor, ui::FrameLogLine& line);
// Where an editor window falls short of usable; empty when it is visible (for UI test checks).
std::string windowProblem(ui::EditorWindow which);

}  // namespace gbl
