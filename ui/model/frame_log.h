// --log-frames: one JSON line per editor frame, so tests driving the real window from outside
// (xdotool) can read what each frame did.
#pragma once

#include <glm/glm.hpp>

#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gbl::ui {

// A light a click at (x, y) in window coordinates would select (the test clicks there).
struct PickableLight {
    int index = -1;
    glm::vec2 window{0.0f};
};

struct FrameLogLine {
    long frame = 0;
    bool rendered = false;         // the renderer ran (render on change)
    std::string renderReason;      // what changed ("camera, lights"), "nothing" when it did not run
    double frameMs = 0.0;          // wall clock of the whole loop iteration
    glm::vec3 camera{0.0f};        // camera position
    glm::vec2 cameraAngles{0.0f};  // yaw, pitch in degrees
    int selectedLight = -1;
    bool textInput = false;  // a text field has the keyboard
    bool viewportHovered = false;
    glm::vec4 viewport{0.0f};  // the viewport image in window coordinates: x, y, width, height
    // Each G-buffer viewer's image at zoom 1 (kViewerNames order), x, y, width, height in window
    // coordinates, written as one flat array of numbers; all 0 while the window is hidden.
    std::vector<glm::vec4> viewerImages;
    std::vector<PickableLight> pickable;
    int accumulate = -1;                     // lights the scrubber accumulates; -1 = off
    glm::vec4 scrubber{0.0f};                // the scrubber's slider in window coordinates
    glm::vec4 abToggle{0.0f};                // the viewport's A/B checkbox
    glm::vec4 pinLit{0.0f};                  // the viewport's "Pin lit" button
    glm::vec4 litDiff{0.0f};                 // ... and its "Diff" checkbox (0 until pinned)
    float abDivider = -1.0f;                 // A/B split: where A ends (share of the image width); -1 = off
    std::vector<double> abEvaluations;       // A/B in the heat view: A's and B's light evaluations summed
    std::vector<std::string> events;         // input events applied this frame, and what they did
    std::vector<std::string> actions;        // editor actions carried out this frame
    std::vector<std::string> clipped;        // UI content cut off this frame, where ImGui can tell
    std::optional<std::string> sessionPath;  // the session file of the editor ("" = untitled)
    // Lessons (ui/editor_lessons.cpp): "ID:STEP" shown ("" = none), the window centres of the
    // Lessons window's buttons (LessonState::buttonCentres; 0, 0 when not drawn), the step's
    // prediction ("" none made, "right", "wrong"), whether its answer is shown, the debug view.
    std::string lesson;
    std::string lessonPrediction;
    bool lessonAnswer = false;
    std::string lessonTasks;  // the step's checklist: one '1' (met) or '0' per task
    // The step's region: the text lines it shows in view (its visible height over the line height;
    // 0 while no lesson is open) and the Lessons window (x, y, width, height; 0 while not drawn).
    float lessonLines = 0.0f;
    int lessonHints = 0;  // the tasks' hints shown below it
    glm::vec4 lessonsWindow{0.0f};
    bool lessonGlossary = false;     // the Glossary window is open
    std::string lessonGlossaryTerm;  // the term it last opened at ("" = none)
    std::vector<glm::vec2> lessonButtons;
    std::vector<float> lessonMark;  // the viewport's lesson mark: x, y (renderer pixels), value; empty: none
    // The course view (issue 27): each lesson's row and its Restart button, x, y, width, height in
    // window coordinates as flat arrays (0 while not wholly in view); each lesson's progress as
    // "ID steps/steps tasks/tasks right/asked", lessons joined by '|'; the "Next lesson" button at
    // a lesson's last step (0 while not drawn).
    std::vector<glm::vec4> courseRows;
    std::vector<glm::vec4> courseRestart;
    std::string courseProgress;
    glm::vec4 nextLesson{0.0f};
    std::string view;
    // What this context cannot run (issue 50): the lighting mode in use, the shown step's note
    // ("" when it runs) and each lesson's note in the course, in the lessons' order.
    std::string mode;
    std::string lessonNote;
    std::vector<std::string> courseNotes;
    // The menu bar's status (its newest log line and the context) and, in the browser, the lines of
    // Help > About this browser.
    std::string status;
    std::vector<std::string> browserLimits;
    // The G-buffer layout in use, the Pipeline window, its layout combo (0 while not visible) and,
    // while its list is open, the centre of each entry (kGBufferLayoutNames order).
    std::string layout;
    glm::vec4 pipelineWindow{0.0f};
    glm::vec4 layoutCombo{0.0f};
    std::vector<glm::vec2> layoutItems;
    // msaa (issue 47): the Pipeline window's msaa combo and its open list's entries (as the layout
    // combo's), the samples of the frame shown, the viewport's "Complex" checkbox and the position
    // viewer's sample selector (0 while not drawn) with its sample (-1 = all).
    glm::vec4 msaaCombo{0.0f};
    std::vector<glm::vec2> msaaItems;
    std::vector<int> msaaGreyed;  // per open entry: 1 where greyed out with a reason
    int msaaSamples = 0;
    glm::vec4 msaaComplexBox{0.0f};
    glm::vec4 positionSampleCombo{0.0f};
    int positionSample = -1;
    // The viewport's tools: the texel size of the image they read and their Shift+drag region as
    // x, y, width, height in texels (width 0 while none; -1 = tools closed).
    glm::ivec2 toolsImage{0};
    glm::ivec4 toolsRegion{-1, -1, -1, -1};
    // The Frame window (model/frame_diagram.h): its rectangle (0 while closed), the Stats button
    // that opens it, the selected pass's "Stop here" button, what a click may land on
    // ("pass:NAME@X,Y", "in:PASS:RESOURCE@X,Y", "out:..."), the stop the editor asks for and the
    // pass the frame shown stopped after ("" = none).
    glm::vec4 frameWindow{0.0f};
    glm::vec4 frameButton{0.0f};
    glm::vec4 stopButton{0.0f};
    std::vector<std::string> frameTargets;
    std::string stopAfter;
    std::string stoppedAfter;
    // Markers and overlays (issue 26): the lights whose volume holds the camera (the viewport
    // says so), the light volumes the wireframes outline, the viewport's "Wireframes" and "all"
    // checkboxes, whether the lit diff is shown and the inspector lists every light.
    std::vector<int> cameraInside;
    int wireframes = 0;
    glm::vec4 wireframesToggle{0.0f};
    glm::vec4 wireframesAll{0.0f};
    bool litDiffShown = false;
    bool everyLight = false;
    // An open G-buffer's Checks button, its findings' count, the first finding's radio button in
    // the open list (0 while the list is closed), the marked finding (-1: none) and the precision
    // lines the open list drew (0 while it is closed).
    glm::vec4 checksButton{0.0f};
    int findings = 0;
    glm::vec4 firstFinding{0.0f};
    int markedFinding = -1;
    int precisionLines = 0;
    // The attachment overview: whether the viewport shows it, its toolbar button, and each cell's
    // picture as "VIEW@X,Y,W,H" (kDebugViewNames name, window coordinates; empty while off).
    bool overview = false;
    glm::vec4 overviewButton{0.0f};
    std::vector<std::string> overviewCells;
    // The presentation layout (panels/panel_presentation.h): on or off, its caption's rectangle (0
    // while off) and View > Presentation's row (0 unless the menu is open).
    bool presentation = false;
    glm::vec4 presentationCaption{0.0f};
    glm::vec4 presentationItem{0.0f};
    float uiScale = 1.0f;        // the UI scale in use (model/ui_scale.h: View > UI scale, --ui-scale)
    glm::vec2 viewerArea{0.0f};  // the first G-buffer viewer's image area (GBufferPanelState::imageArea)
    std::string dockLayout;      // the kind of default dock layout last built (model/layout_state.h, dockLayoutName)
    // Each editor window's dock node as "NAME=ID" (ID in hex, 0 when floating or not drawn) and its
    // tab (docked) or title bar (floating) as one flat array of rectangles, in EditorWindow order
    // (model/layout_state.h): a window dragged into another's tab bar then shares its ID.
    std::vector<std::string> docks;
    std::vector<glm::vec4> windowTabs;
    // The Lights window's attenuation plot (issue 26): its rectangle and the Kq field's (x, y, width,
    // height in window coordinates; 0 unless drawn and wholly in view), the radius it marks and
    // its ghost's, the radius before the current drag (-1 when not drawn / no ghost).
    glm::vec4 lightsWindow{0.0f};  // the Lights window (0 while collapsed or hidden)
    glm::vec4 plotRect{0.0f};
    glm::vec4 kqField{0.0f};
    float plotRadius = -1.0f;
    float plotGhostRadius = -1.0f;
    glm::vec4 plotPopup{0.0f};      // the plot beside the pointer during a drag (LightsPanelState::plotPopupRect)
    float plotPopupRadius = -1.0f;  // the radius it marks
    // The plotted light's inputs to its radius, Kc, Kl, Kq, Imax (intensity times the largest
    // colour channel) and the cut-off, so a test can solve the radius itself (empty when not drawn).
    std::vector<float> plotLight;
    // The imported G-buffer shown instead of the scene ("" = the scene; model/gbuffer_opening.h)
    // and the size of the frame the renderer drew, which is that G-buffer's while it is open.
    std::string gbuffer;
    glm::ivec2 frameSize{0};
    // The menu bar's "File", File > "Open G-buffer..." while that menu is open, and whether the
    // G-buffer file browser is open.
    glm::vec4 fileMenu{0.0f};
    glm::vec4 viewMenu{0.0f};             // the menu bar's "View"
    glm::vec4 resetLayoutItem{0.0f};      // View > Reset layout (0 unless the menu is open)
    glm::vec4 uiScaleMenu{0.0f};          // View > UI scale (0 unless the menu is open)
    std::vector<glm::vec4> uiScaleItems;  // its choices, model/ui_scale.h order (empty unless open)
    glm::vec4 openGBufferItem{0.0f};
    glm::vec4 openSceneItem{0.0f};  // File > "Open scene..." (0 while the menu is closed)
    // The browser build's File > "Open folder..." and "Save window as PNG", and File > "Export all..."
    // (0 while the menu is closed, and the first two always natively).
    glm::vec4 openFolderItem{0.0f};
    glm::vec4 exportAllItem{0.0f};
    glm::vec4 windowShotItem{0.0f};
    bool gbufferBrowser = false;
    // File > "Capture a program..." (0 while the menu is closed), whether its dialog is open, the
    // dialog's command, frame and folder fields, its EGL choice and its Capture button (0 unless
    // drawn), whether a capture runs and the last refusal's sentence.
    glm::vec4 captureItem{0.0f};
    bool captureDialog = false;
    glm::vec4 captureCommand{0.0f};
    glm::vec4 captureFrame{0.0f};
    glm::vec4 captureOut{0.0f};
    glm::vec4 captureEgl{0.0f};
    glm::vec4 captureButton{0.0f};
    bool capturing = false;
    std::string captureError;
    // How the renderer's passes were timed (FrameStats::timingSource) and the last timings shown,
    // [pass name, milliseconds] pairs (a frame or more old where the GPU is read without waiting).
    std::string timing;
    std::vector<std::pair<std::string, double>> passMs;
};

std::string frameLogJson(FrameLogLine const& line);

// The open log file; writes and flushes one line per frame so a reader sees it at once.
class FrameLog {
public:
    // nullopt on success, else one sentence.
    std::optional<std::string> open(std::string const& path);
    bool isOpen() const { return file_ != nullptr; }
    void write(FrameLogLine const& line);

private:
    struct Close {
        void operator()(std::FILE* f) const { std::fclose(f); }
    };
    std::unique_ptr<std::FILE, Close> file_;
};

}  // namespace gbl::ui
