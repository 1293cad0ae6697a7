// A student's progress through the course: per lesson, the steps seen, the tasks done, the
// predictions answered and the step to come back to. Plain values and pure functions, no ImGui,
// no files (session/lesson_progress_file.h reads and writes it); tests/lesson_progress_test.cpp.
#pragma once

#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gbl::ui {

// One step's record. Steps and tasks are 0-based here (the file writes them 1-based, as
// `--lesson ID:STEP` names steps).
struct StepProgress {
    std::vector<int> tasksDone;      // indices of the step's tasks met at least once, sorted
    std::optional<bool> prediction;  // the first prediction made at this step: right or not
    bool operator==(StepProgress const&) const = default;
};

struct LessonProgress {
    int at = 0;                         // the step the student last saw: where the lesson reopens
    std::map<int, StepProgress> steps;  // the steps seen
    bool operator==(LessonProgress const&) const = default;
};

// Keyed by lesson id. A lesson the library no longer has, or a step past a lesson's end, is kept
// as it was read (a lesson folder may be incomplete for a while; its progress comes back with
// it) and left out of the counts.
struct CourseProgress {
    std::map<std::string, LessonProgress, std::less<>> lessons;
    bool operator==(CourseProgress const&) const = default;
};

// A lesson's shape as the counts need it: per step, its number of tasks and whether it asks for
// a prediction.
struct LessonShape {
    std::vector<int> tasks;
    std::vector<bool> predicts;
};

// What the course view shows for one lesson.
struct LessonCounts {
    int stepsSeen = 0, steps = 0;
    int tasksDone = 0, tasks = 0;
    int predictionsRight = 0, predictionsAsked = 0;  // asked: predictions the student made
    bool operator==(LessonCounts const&) const = default;
};
LessonCounts countProgress(CourseProgress const& progress, std::string_view lesson, LessonShape const& shape);

// Each returns whether it changed the progress (so that the caller saves only then).
// The student sees `step`: it counts as seen and becomes where the lesson reopens.
bool markStepSeen(CourseProgress& progress, std::string_view lesson, int step);
// A task of the step was met.
bool markTaskDone(CourseProgress& progress, std::string_view lesson, int step, int task);
// A prediction was made at the step; only the first one counts (the answer is known after it).
bool markPrediction(CourseProgress& progress, std::string_view lesson, int step, bool right);
// "Restart": forgets one lesson's progress, and only that lesson's.
bool restartLesson(CourseProgress& progress, std::string_view lesson);

// The step the lesson reopens at, within 0..stepCount-1 (0 for a lesson never opened).
int resumeStep(CourseProgress const& progress, std::string_view lesson, int stepCount);

}  // namespace gbl::ui
