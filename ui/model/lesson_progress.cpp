// A student's progress through the course (see lesson_progress.h).
#include "model/lesson_progress.h"

#include <algorithm>

namespace gbl::ui {

namespace {

LessonProgress& findOrAdd(CourseProgress& progress, std::string_view lesson) {
    auto it = progress.lessons.find(lesson);
    if (it == progress.lessons.end()) it = progress.lessons.emplace(std::string(lesson), LessonProgress{}).first;
    return it->second;
}

}  // namespace

LessonCounts countProgress(CourseProgress const& progress, std::string_view lesson, LessonShape const& shape) {
    LessonCounts c;
    c.steps = int(shape.tasks.size());
    for (int n : shape.tasks) c.tasks += n;
    auto it = progress.lessons.find(lesson);
    if (it == progress.lessons.end()) return c;
    for (auto const& [step, s] : it->second.steps) {
        if (step < 0 || step >= c.steps) continue;  // a step past the lesson's end: kept, not counted
        ++c.stepsSeen;
        int const tasks = shape.tasks[std::size_t(step)];
        c.tasksDone +=
            int(std::count_if(s.tasksDone.begin(), s.tasksDone.end(), [&](int t) { return t >= 0 && t < tasks; }));
        bool const predicts = std::size_t(step) < shape.predicts.size() && shape.predicts[std::size_t(step)];
        if (predicts && s.prediction) {
            ++c.predictionsAsked;
            c.predictionsRight += *s.prediction ? 1 : 0;
        }
    }
    return c;
}

bool markStepSeen(CourseProgress& progress, std::string_view lesson, int step) {
    if (step < 0) return false;
    LessonProgress& l = findOrAdd(progress, lesson);
    bool const changed = l.at != step || !l.steps.contains(step);
    l.at = step;
    l.steps[step];
    return changed;
}

bool markTaskDone(CourseProgress& progress, std::string_view lesson, int step, int task) {
    if (step < 0 || task < 0) return false;
    std::vector<int>& done = findOrAdd(progress, lesson).steps[step].tasksDone;
    auto it = std::lower_bound(done.begin(), done.end(), task);
    if (it != done.end() && *it == task) return false;
    done.insert(it, task);
    return true;
}

bool markPrediction(CourseProgress& progress, std::string_view lesson, int step, bool right) {
    if (step < 0) return false;
    std::optional<bool>& p = findOrAdd(progress, lesson).steps[step].prediction;
    if (p) return false;
    p = right;
    return true;
}

bool restartLesson(CourseProgress& progress, std::string_view lesson) {
    auto it = progress.lessons.find(lesson);
    if (it == progress.lessons.end()) return false;
    progress.lessons.erase(it);
    return true;
}

int resumeStep(CourseProgress const& progress, std::string_view lesson, int stepCount) {
    auto it = progress.lessons.find(lesson);
    if (it == progress.lessons.end() || stepCount <= 0) return 0;
    return std::clamp(it->second.at, 0, stepCount - 1);
}

}  // namespace gbl::ui
