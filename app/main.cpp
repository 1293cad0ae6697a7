// gbuffer-lab entry point: the editor by default, `render` and `bench` as sub-commands.
#include "bench_command.h"
#include "bench_layouts.h"
#include "capture/capture_command.h"
#include "check_command.h"
#include "cli_options.h"
#include "cli_values.h"
#include "compare_command.h"
#include "editor_cli.h"
#include "lesson_command.h"
#include "render_command.h"

#include <CLI/CLI.hpp>

#include <cstdio>

int main(int argc, char** argv) {
    CLI::App app{"gbuffer-lab: a deferred-shading editor that shows every step of the frame"};
    app.require_subcommand(0, 1);

    // The editor (no sub-command).
    gbl::EditorCli editor;
    gbl::addEditorOptions(app, editor);

    gbl::RenderOptions renderOptions;
    CLI::App* render = app.add_subcommand("render", "Render one frame headlessly and write every intermediate image");
    gbl::addRenderOptions(*render, renderOptions);

    gbl::BenchOptions benchOptions;
    CLI::App* bench = app.add_subcommand("bench", "Measure GPU time per pass for lighting modes and light counts");
    gbl::addBenchOptions(*bench, benchOptions);

    gbl::LessonsOptions lessonsOptions;
    CLI::App* lessons = app.add_subcommand("lessons", "List the guided lessons and their steps");
    gbl::addLessonsOptions(*lessons, lessonsOptions);
    gbl::CompareOptions compareOptions;
    CLI::App* compare = app.add_subcommand("compare", "Render two session files and diff their lit frames");
    gbl::addCompareOptions(*compare, compareOptions);
    gbl::CheckOptions checkOptions;
    CLI::App* check = app.add_subcommand("check", "Open another program's G-buffer and list what looks wrong in it");
    gbl::addCheckOptions(*check, checkOptions);
    gbl::CaptureOptions captureOptions;
    CLI::App* capture = app.add_subcommand(
        "capture", "Record a frame of another OpenGL deferred renderer with apitrace and write its G-buffer manifest");
    gbl::addCaptureOptions(*capture, captureOptions);

    try {
        app.parse(argc, argv);
    } catch (CLI::ParseError const& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help and friends
        // One sentence and exit code 2 for every bad argument, as the other errors do.
        std::fprintf(stderr, "gbuffer-lab: %s (see --help)\n", e.what());
        return 2;
    }
    if (render->parsed()) return gbl::runRender(renderOptions);
    if (lessons->parsed()) return gbl::runLessons(lessonsOptions);
    if (compare->parsed()) return gbl::runCompare(compareOptions);
    if (check->parsed()) return gbl::runCheck(checkOptions);
    if (capture->parsed()) return gbl::runCapture(captureOptions, argv[0]);
    if (bench->parsed()) {
        benchOptions.lightsGiven = bench->count(gbl::cli::kLights.name) > 0;
        return gbl::runBenchLayouts(benchOptions);
    }

    if (auto const exitCode = gbl::finishEditorOptions(editor)) return *exitCode;
    return gbl::runEditor(editor.editor);
}
