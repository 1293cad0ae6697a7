// gbuffer-lab in the browser (issue 29): the same editor as on the desktop, in the page's canvas
// through WebGL2. The page (app/web/index.html) turns the URL's query into the command line
// (?lesson=camera_inside:2&log-frames=/dev/stdout is `--lesson camera_inside:2 --log-frames
// /dev/stdout`), so the editor's options work as they do natively; the editor's window is the
// canvas, at the page's size unless --size is given.
#include "editor_cli.h"
#include "lesson_check.h"

#include <emscripten/emscripten.h>
#include <emscripten/html5.h>
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv) {
    CLI::App app{"gbuffer-lab in the browser: a deferred-shading editor that shows every step of the frame"};
    gbl::EditorCli cli;
    gbl::addEditorOptions(app, cli);
    std::string checkLessons, benchRenderer;
    app.add_option("--check-lessons", checkLessons,
                   "Check shipped lessons' claims in WebGL2 instead of opening the editor: all, or ID:STEP,...");
    app.add_option("--bench-renderer", benchRenderer,
                   "Time the renderer alone in WebGL2 (a lighting mode) instead of opening the editor");
    try {
        app.parse(argc, argv);
    } catch (CLI::ParseError const& e) {
        std::fprintf(stderr, "gbuffer-lab: %s (the page's URL query gives the options)\n", e.what());
        return 2;
    }
    if (auto const exitCode = gbl::finishEditorOptions(cli)) return *exitCode;
    if (!checkLessons.empty() || !benchRenderer.empty()) {
        // No editor: the page's loading line (app/web/index.html) goes now, not at a first frame.
        EM_ASM({
            if (Module['gblShowEditor']) Module['gblShowEditor']();
        });
        return !checkLessons.empty() ? gbl::checkLessonsInBrowser(checkLessons)
                                     : gbl::benchRendererInBrowser(benchRenderer);
    }
    if (!cli.editor.sizeGiven) {
        int width = 0, height = 0;
        emscripten_get_canvas_element_size("#canvas", &width, &height);
        if (width > 0 && height > 0) {
            cli.editor.width = width;
            cli.editor.height = height;
        }
        cli.editor.sizeGiven = true;
    }
    // Exceptions are compiled in (cmake/web.cmake); one that reaches here is printed, not an "Uncaught <number>".
    try {
        return gbl::runEditor(cli.editor);
    } catch (std::exception const& e) {
        std::fprintf(stderr, "gbuffer-lab: error: %s\n", e.what());
        return 1;
    }
}
