// The course progress file: $XDG_CONFIG_HOME/gbuffer-lab/lesson_progress.json (the config folder of
// session/config_dir.h), a small versioned JSON file written whenever progress changes.
#pragma once

#include "model/lesson_progress.h"
#include "session/lesson_file.h"

#include <optional>
#include <string>
#include <string_view>

namespace gbl::ui {

inline constexpr std::string_view kProgressFormat = "gbuffer-lab-lesson-progress";
inline constexpr int kProgressVersion = 1;
inline constexpr std::string_view kProgressFileName = "lesson_progress.json";

struct ProgressLoad {
    CourseProgress progress;  // empty unless read whole
    bool missing = false;     // no file yet: no progress, and nothing wrong
    std::string error;        // "<file>: <what is wrong>" for a file that could not be used
};

// The whole file or nothing: a file with any error gives empty progress and the error.
ProgressLoad parseProgress(std::string_view text, std::string const& fileLabel);
ProgressLoad loadProgress(std::string const& path);
// The file's text (steps and tasks written 1-based).
std::string progressToJson(CourseProgress const& progress);
// Writes the file atomically; one sentence naming the file and the reason on failure.
std::optional<std::string> saveProgress(std::string const& path, CourseProgress const& progress);
// Moves a file that could not be read aside to `<path>.broken` (replacing an older one) before it
// is first written over, so that the student's old file can still be looked at.
std::optional<std::string> keepBrokenProgress(std::string const& path);

// The progress file in the config folder; nullopt with the reason when there is no folder to be had.
std::optional<std::string> progressFilePath(std::string* why);

// The counts' view of a lesson: its tasks and predictions per step.
LessonShape lessonShape(Lesson const& lesson);

}  // namespace gbl::ui
