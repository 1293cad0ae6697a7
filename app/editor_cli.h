// The editor's command-line options (no sub-command), shared by the desktop entry point
// (app/main.cpp) and the browser's (app/web/main.cpp, which reads them from the page's URL).
#pragma once

#include "editor/editor.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace gbl {

struct EditorCli {
    EditorOptions editor;
    std::optional<std::string> scene;
    std::string windowSize;
    bool noVsync = false;
};

// Adds the editor's options to `app`, bound to `cli`.
void addEditorOptions(CLI::App& app, EditorCli& cli);

// After parsing: checks the values and completes cli.editor. Returns an exit code (2) after
// printing one sentence when a value is bad.
std::optional<int> finishEditorOptions(EditorCli& cli);

}  // namespace gbl
