// `gbuffer-lab lessons [--json]` and `gbuffer-lab render --lesson ID[:STEP]`.
#pragma once

#include "render_command.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace gbl {

struct LessonsOptions {
    bool json = false;
    std::optional<std::string> dir;  // instead of assets/lessons
};

void addLessonsOptions(CLI::App& sub, LessonsOptions& options);
// Lists every lesson and its steps; 2 when a lesson file is broken (after listing the good ones).
int runLessons(LessonsOptions const& options);

// `render --lesson`: the step's frame with the same files as `render`, plus claim.json.
int runRenderLesson(RenderOptions const& options);

}  // namespace gbl
