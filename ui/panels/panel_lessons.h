// The Lessons window: the course (every lesson with the student's progress), a lesson's steps with
// their text's live values, leaving it; and saving the editor's state as a new lesson step, or
// opening a lesson file.
#pragma once

#include "model/file_browser.h"
#include "model/lesson_progress.h"
#include "model/lesson_state.h"
#include "model/lesson_text.h"
#include "session/glossary_file.h"
#include "session/lesson_file.h"

#include <span>
#include <string>

namespace gbl::ui {

// A `placement` of non-zero size (x, y, width, height) draws the window there, undocked and fixed,
// under its own name, as the presentation layout places it beside the image; the docked Lessons
// window keeps its place in the dock tree meanwhile.
// Requests go into `state` (startRequest, stepRequest, leaveRequested, saveStepRequested,
// openRequested, predictRequested, glossaryRequested, restartRequest); the editor loop carries them out. `values` fill
// the text's placeholders. `counts` is each lesson's progress, in the order of `lessons`.
void drawLessonsPanel(LessonState& state, std::span<Lesson const> lessons, std::span<LessonCounts const> counts,
                      std::span<std::string const> loadErrors, LessonValues const& values, FileBrowserState& browser,
                      Glossary const& glossary, glm::vec4 placement = glm::vec4(0.0f));

}  // namespace gbl::ui
