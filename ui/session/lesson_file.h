// Lesson files: one versioned JSON file per lesson in assets/lessons/, each step a whole editor
// state (parsed by the session code, so every pipeline setting a session knows a lesson knows),
// its text and an optional machine-checked claim. Messages name the file and the field.
#pragma once

#include "model/lesson_state.h"
#include "model/lesson_tasks.h"
#include "session/session.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gbl::ui {

inline constexpr std::string_view kLessonFormat = "gbuffer-lab-lesson";
// Bump when a field changes meaning or a required field is added.
// Version 2: every step has an answer; a step may carry a prediction.
inline constexpr int kLessonVersion = 2;

struct LessonStep {
    LessonText text;
    LessonSnapshot state;  // camera, lights, pipeline, viewers, selection, pixel
    int defaultSceneLights = 32;
    bool defaultSceneGlass = false;  // "scene": {"glass": true}: the default scene with its glass panes
    std::optional<LessonClaim> claim;
    std::optional<LessonPrediction> predict;
    std::vector<LessonTask> tasks;  // the checklist the editor ticks live
    std::string tasksJson;          // `tasks` as written in the file, for writing it back
};

struct Lesson {
    std::string id;  // letters, digits, '_' and '-': what `render --lesson ID:STEP` names
    std::string title;
    std::string summary;
    // A glTF scene the lesson is about (its "scene" field, as written), and that file found (the
    // lesson's folder first, then sharedModelsDir()); both empty: the default scene.
    std::string scene;
    std::string scenePath;
    int width = 640;  // the frame size the lesson's pixels and claims were measured at
    int height = 360;
    std::vector<LessonStep> steps;
    std::string path;  // the file it came from
};

struct LessonLoad {
    std::optional<Lesson> lesson;
    std::string error;  // "<file>: <field> <what is wrong>" when lesson is empty
};

// fileLabel names the file in messages; its folder is where a relative "scene" is looked for first.
LessonLoad parseLesson(std::string_view text, std::string const& fileLabel);
LessonLoad loadLesson(std::string const& path);

struct LessonLibrary {
    std::vector<Lesson> lessons;      // sorted by file name
    std::vector<std::string> errors;  // one sentence per file that failed
};

// Every *.json in `dir`, in file-name order. Duplicate ids are an error of the later file.
LessonLibrary loadLessonDir(std::string const& dir);
// assets/lessons of the source tree, or $GBL_LESSONS_DIR when set.
std::string defaultLessonDir();
// Where a lesson's "scene" is looked for after the lesson's own folder: ../shared/gltf beside the
// source tree, or $GBL_SHARED_GLTF_DIR when set. The folder may be absent.
std::string sharedModelsDir();

// The scene a step is shown on, as EditorState::sceneName names it: the lesson's glTF file, or the
// default scene, "default+glass" (kDefaultSceneGlass) when the step asks for its glass panes.
std::string lessonStepScene(Lesson const& lesson, int step);

// "ID" or "ID:STEP" (STEP counted from 1) to the lesson's index and the step's index; an
// error sentence listing the lessons otherwise.
struct LessonRef {
    int lesson = -1;
    int step = 0;
    std::string error;
};
LessonRef findLessonStep(LessonLibrary const& library, std::string_view ref);

// The lesson as JSON, every step written in full (camera, lights, pipeline, viewers).
std::string lessonToJson(Lesson const& lesson);
// One task as a lesson file writes it: kind, goal, hint and its kind's fields, a setting's value
// as a session file writes it ("off", true, 0.6). parseLesson reads it back to the same task.
std::string taskToJson(LessonTask const& task);
// A prediction as a lesson file writes it (prompt, choices and correct or number and tolerance,
// explain, before).
std::string predictionToJson(LessonPrediction const& prediction);
// Appends `step` to the lesson in `path` (creating it, with the id taken from the file name,
// when the file does not exist); the error sentence on failure. The file is written atomically.
// scenePath: the glTF file the step was set up on ("" for the default scene): a new lesson names
// it as its "scene"; an existing lesson on another scene is refused.
std::optional<std::string> appendLessonStep(std::string const& path, LessonStep const& step,
                                            std::string const& scenePath = {});

}  // namespace gbl::ui
