// Lessons as the editor plays them: the state a step sets up, the claim it makes, its text, and
// which lesson and step are shown with the editor state to return to. Plain values, no ImGui.
#pragma once

#include "model/ab_compare.h"

#include "core/camera.h"
#include "core/frame_types.h"
#include "core/pipeline_settings.h"
#include "core/point_light.h"
#include "model/editor_state.h"
#include "model/lesson_tasks.h"
#include "model/lights_state.h"
#include "model/viewer_state.h"

#include <glm/glm.hpp>

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gbl::ui {

// Everything a lesson step sets, and everything leaving a lesson puts back.
// The viewport's A/B comparison a step opens: side B's overridden fields and the view.
struct LessonAb {
    AbView view = AbView::Split;
    PipelineSettings b;           // B's values of the overridden fields
    std::vector<bool> overrides;  // one per abFields() row
};

// The viewport's light-by-light scrubber the step opens: the frame lit by lights 0..light, or, with
// `only`, that light's own term (the scrubber's "only k", k = light + 1).
struct LessonLightByLight {
    int light = 0;
    bool only = false;
};

struct LessonSnapshot {
    Camera camera;
    std::vector<PointLight> lights;
    PipelineSettings pipeline;
    std::array<ViewerState, 5> viewers = GBufferPanelState::defaultViewers();
    LightAnimation animation;
    int selectedLight = -1;
    int activeViewer = 0;
    // The pixel the step is about, as fractions of the frame (0..1, top-left origin), so that it
    // names the same surface point at any viewport size; the inspector is locked on it.
    std::optional<glm::vec2> pixel;
    // The A/B split or diff the step opens; nullopt turns A/B off.
    std::optional<LessonAb> ab;
    // The light-by-light scrubber the step opens; nullopt turns it off.
    std::optional<LessonLightByLight> lightByLight;
    // "lit_pin": the step pins the lit frame it shows (read at the next frame) and the viewport shows
    // |now - pinned| (Pin lit + Diff), so what the student changes lights up; a step without it
    // turns the diff off (the pin stays).
    bool litPinDiff = false;
    // Only for returning from a lesson: the inspector as it was.
    bool inspectorLocked = false;
    std::optional<glm::ivec2> inspectorPixel;
};

// What leaving a lesson puts back: the snapshot, and the tools a student may have used during the
// lesson, which its steps never set (so they would otherwise follow the student out of it): the
// viewport's Tools and its viewer, the lit pin and its diff, the inspector's "every light", the
// scrubber, A/B's diff settings and the Frame window's stop.
struct LessonReturn {
    LessonSnapshot snapshot;
    bool toolsOpen = true;
    ViewerState toolsViewer;
    bool litDiff = false;
    std::optional<FloatImage> litPinned;
    long litPinnedFrame = -1;
    bool everyLight = false;
    AccumulateState accumulate;
    float abDivider = 0.5f;
    DiffMode abDiffMode = DiffMode::Absolute;
    float abThreshold = 0.0f;
    bool abHeatToThreshold = false;
    AbMetric abMetric = AbMetric::Lit;
    float abAngleThreshold = 1.0f;
    std::optional<PassId> stopAfter;
};
LessonReturn captureLessonReturn(EditorState const& state);
void applyLessonReturn(LessonReturn const& r, EditorState& state, glm::ivec2 frameSize);

// The snapshot of the editor now (pixel left empty: the inspector's pixel is kept as is).
LessonSnapshot captureLessonSnapshot(EditorState const& state);
// Applies every field; `frameSize` turns the step's pixel into an inspector pixel.
void applyLessonSnapshot(LessonSnapshot const& snapshot, EditorState& state, glm::ivec2 frameSize);
// The renderer pixel (top-left origin) of a pixel given as fractions, clamped into the frame.
glm::ivec2 lessonPixel(glm::vec2 fraction, glm::ivec2 frameSize);

// --- claims --------------------------------------------------------------------------------
// A small fixed vocabulary: each kind is checked by one function (model/lesson_claims.h) over
// real read-back images, and every shipped step's claim is asserted by a GL test.
enum class ClaimKind {
    MatchesCpu,           // lit value at the pixel = ambient + every light, on the CPU (shading_cpu.h)
    LosesLight,           // reference lit - step lit at the pixel = the CPU contribution of `light`
    SameImage,            // the lit image equals the reference's within max_abs everywhere
    FewerLitPixels,       // at least min_fraction of the reference's lit pixels are dark in the step
    PositionError,        // |stored position - position rebuilt from depth| < bound on every pixel
    TileCountMatchesCpu,  // lights listed for the pixel's tile = the CPU tile test (tile_math.h)
    ExecutedExceedsLit,   // at the pixel, more lights were evaluated than lit it (coverage x > y)
    AttachmentEquals,     // an attachment's value at the pixel equals `value` within tolerance
    DiffersFrom,          // at least min_fraction of the covered pixels differ from the reference by > bound
    FewerEvaluations,     // the heat map's evaluations, summed, are min_fraction .. max_fraction fewer than the
                          // reference's
    ComplexShare,         // msaa: the share of complex pixels is min_fraction .. max_fraction
};
struct LessonClaim {
    ClaimKind kind = ClaimKind::MatchesCpu;
    int light = -1;                             // loses_light
    std::optional<PipelineSettings> reference;  // loses_light, same_image, fewer_lit_pixels, differs_from
    float tolerance = 0.02f;                    // matches_cpu, loses_light, attachment_equals (relative + absolute)
    float bound = 0.0f;                         // position_error_below, same_image and differs_from (abs difference)
    float atLeast = 0.0f;  // position_error_below (optional): the largest error is at least this (a range)
    // position_error_below (optional): the editor measures the claim on its own frame and marks the
    // pixel of the largest error in the viewport, with its value.
    bool mark = false;
    bool most = false;         // tile_count_matches_cpu (optional): the pixel's tile lists the most lights of the frame
    float minFraction = 0.0f;  // fewer_lit_pixels, differs_from, fewer_evaluations
    // differs_from, fewer_evaluations (optional): below this share (a range, for a stated count)
    float maxFraction = 1.0f;
    int reached = -1;  // matches_cpu (optional): how many lights add a visible amount at the pixel; -1 = unchecked
    Attachment attachment = Attachment::Normal;  // attachment_equals
    glm::vec4 value{0.0f};                       // attachment_equals
    unsigned compare = 0x7;                      // attachment_equals: bit i = component i is compared
    // same_image, differs_from: which image is compared, the lit image (the light sum) or the display
    // image (Attachment::Final), which alone shows the overlays (light cubes, wireframes).
    Attachment image = Attachment::Lighting;
};

// --- text ------------------------------------------------------------------------------------

struct LessonText {
    std::string title;
    std::string look;      // what to look at
    std::string equation;  // with {placeholders} for live values
    std::string question;  // what to answer with the tool
    std::string answer;    // revealed on request, after the student has tried (same placeholders)
};

// --- predictions -------------------------------------------------------------------------------
// A step may ask for a prediction before it reveals: the editor shows `before` (when given), the
// student picks a choice or types a number, then the step's own state is applied and the
// explanation is shown with whether the prediction was right.
struct LessonPrediction {
    std::string prompt;                    // what to predict
    std::vector<std::string> choices;      // multiple choice; empty for a number
    int correct = -1;                      // index into choices
    float number = 0.0f;                   // the right number (when choices is empty)
    float tolerance = 0.0f;                // |typed - number| <= tolerance is right
    std::string explain;                   // shown after the prediction (placeholders allowed)
    std::optional<LessonSnapshot> before;  // the state shown while the student predicts
    std::string beforeJson;                // `before` as written in the file, for writing it back
};

// Whether a prediction is right: the picked choice for multiple choice, the typed number otherwise.
bool predictionRight(LessonPrediction const& p, int choice, float typed);

// --- what the Lessons window shows and asks for -------------------------------------------------

struct LessonState {
    int lesson = -1;  // index into the editor's lesson list; -1 = no lesson running
    int step = 0;
    std::optional<LessonReturn> before;  // the editor before the lesson started
    std::string sceneBefore;             // its scene ("default" or the glTF path), reloaded on Leave

    // Requests from the window, carried out by the editor loop (it knows the frame size and undo).
    int startRequest = -1;  // a lesson was picked
    int stepRequest = -1;   // go to this step of the running lesson
    bool leaveRequested = false;
    bool saveStepRequested = false;  // "Save the current state as a lesson step"
    bool openRequested = false;      // open a lesson file (openPath)
    std::string openPath;
    std::string savePath = "my_lesson.json";  // where saved steps go
    LessonText draft;                         // text typed for the step being saved
    // "Add tasks" when saving: the saved step shows the state remembered here (taskStartRequested
    // remembers the editor's), and its tasks ask for the change from it to the editor's state now
    // (tasksFromChange).
    std::optional<LessonSnapshot> taskStart;
    bool taskStartRequested = false;
    bool saveWithTasks = false;
    std::string message;  // the last request's outcome (or why it was refused)
    bool messageIsError = false;
    int picked = 0;  // the lesson the list shows selected
    // The step being shown: its prediction and its answer. Reset when the step changes.
    int predictChoice = -1;      // the picked choice, -1 = none yet
    float predictNumber = 0.0f;  // the typed number
    bool predicted = false;      // the prediction was made; the step's state is shown
    bool predictedRight = false;
    bool predictRequested = false;    // "Check my prediction" was pressed: the loop applies the step
    bool answerShown = false;         // "Show answer" was pressed
    std::vector<TaskProgress> tasks;  // the step's checklist: ticked live, hints after kTaskHintSeconds
    bool scrollToResult = false;      // scroll the verdict or the answer into view once drawn
    bool glossaryRequested = false;   // open the glossary (glossaryTerm: at that term, or "")
    std::string glossaryTerm;
    glm::ivec2 pixelFrameSize{0};  // the frame size the step's pixel was placed for; a resize re-places it
    // Window centres of the course's first row, Back, Next, Leave, Show answer, Check my prediction, first
    // choice (or the number field), Glossary and first "Terms:" buttons as last drawn (0, 0 = not
    // drawn or not wholly in view), for UI tests that click them.
    std::array<glm::vec2, 9> buttonCentres{};
    // The course view (shown while no lesson runs): a row's click opens that lesson where the
    // student left it; its Restart clears that lesson's progress. Each row's and each Restart's
    // rectangle (x, y, width, height in window coordinates; 0 unless wholly in view) and the
    // "Next lesson" button at a lesson's last step, as last drawn, for UI tests.
    int restartRequest = -1;
    std::vector<glm::vec4> courseRows;
    std::vector<glm::vec4> courseRestart;
    glm::vec4 nextLessonButton{0.0f};
    // What this context cannot run, in the student's words (the browser has no compute shaders):
    // one note per lesson for the course ("" where every step runs), and the shown step's, which
    // also says what the viewport shows instead. Filled by the editor loop from the renderer.
    std::vector<std::string> lessonNotes;
    std::string stepNote;
    // The step's region (its checklist, prediction, text, question and answer) as last drawn: the text
    // lines it shows in view (its visible height over the line height) and how many pixels it lacks
    // of kLessonRegionLines; the layout grows the Lessons window by that much (panels/layout.h).
    float regionLines = 0.0f;
    float regionShortPx = 0.0f;
    int hintsShown = 0;          // the hints drawn below the region
    glm::vec4 windowRect{0.0f};  // the Lessons window as last drawn (x, y, width, height; 0 when not)
};

// The least text lines a step's region shows while a lesson is open (issue 46: a class reads it).
inline constexpr float kLessonRegionLines = 12.0f;

}  // namespace gbl::ui
