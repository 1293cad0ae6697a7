// The Lessons window: pick a lesson, step through it, read its text with live values, leave it;
// and save the editor's state as a new lesson step, or open a lesson file.
#pragma once

#include "model/file_browser.h"
#include "model/lesson_state.h"
#include "model/lesson_text.h"
#include "session/glossary_file.h"
#include "session/lesson_file.h"

#include <span>
#include <string>

namespace gbl::ui {

// Requests go into `state` (startRequest, stepRequest, leaveRequested, saveStepRequested,
// openRequested, predictRequested, glossaryRequested); the editor loop carries them out. `values` fill the text's
// placeholders.
void drawLessonsPanel(LessonState& state, std::span<Lesson const> lessons, std::span<std::string const> loadErrors,
                      LessonValues const& values, FileBrowserState& browser, Glossary const& glossary);

}  // namespace gbl::ui
