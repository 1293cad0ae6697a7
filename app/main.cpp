// gbuffer-lab entry point: the editor by default, `render` and `bench` as sub-commands.
#include "bench_command.h"
#include "bench_layouts.h"
#include "check_command.h"
#include "cli_options.h"
#include "cli_values.h"
#include "compare_command.h"
#include "editor/editor.h"
#include "lesson_command.h"
#include "model/ui_scale.h"
#include "render_command.h"

#include <CLI/CLI.hpp>

#include <cstdio>

int main(int argc, char** argv) {
    CLI::App app{"gbuffer-lab: a deferred-shading editor that shows every step of the frame"};
    app.require_subcommand(0, 1);

    // The editor (no sub-command).
    gbl::EditorOptions editor;
    std::optional<std::string> scene;
    std::string windowSize;
    bool noVsync = false;
    app.add_option("scene", scene, "A glTF 2.0 file (.gltf or .glb) to open instead of the default scene");
    app.add_option("--screenshot", editor.screenshotPath,
                   "Write the editor window as PNG after --frames frames, then exit");
    app.add_option("--frames", editor.frames, "Frames to run before exiting (0: until the window is closed)");
    gbl::cli::addShared(app, gbl::cli::kSize, windowSize);
    gbl::cli::addShared(app, gbl::cli::kLights, editor.lightCount);
    gbl::cli::addShared(app, gbl::cli::kSession, editor.sessionPath);
    app.add_option("--gbuffer", editor.gbufferPath,
                   "Open another program's G-buffer (a manifest, a folder holding one, or a `render --out` folder) "
                   "and re-light it live (docs/import.md)");
    app.add_option("--ui-test", editor.uiTestScript, "Run a UI test script and exit 0 when every check passes");
    gbl::cli::addShared(app, gbl::cli::kGl, editor.glLimit);
    app.add_flag("--no-vsync", noVsync, "Render as fast as possible");
    gbl::cli::addShared(app, gbl::cli::kAllowOutsideUris, editor.allowOutsideUris);
    app.add_option("--log-frames", editor.logFramesPath,
                   "Write one JSON line per frame to FILE: rendered or not, frame ms, camera, selection, input events");
    app.add_option("--frame-sleep-ms", editor.frameSleepMs,
                   "Sleep this long every frame, still taking input (tests of slow machines)")
        ->check(CLI::Range(0, 10000));
    gbl::cli::addShared(app, gbl::cli::kLesson, editor.lesson);
    app.add_option("--frame-warn-seconds", editor.frameWarnSeconds,
                   "Switch to a faster mode, with a message, before a frame estimated to take longer than this")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--ui-scale", editor.uiScale,
                   "Scale text and controls, 0.75 to 3 (1.5 for a projector); kept with the window layout otherwise");
    app.add_flag("--continuous", editor.continuousRender,
                 "Run the renderer every frame even when nothing changed (for timing)");

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
    if (bench->parsed()) {
        benchOptions.lightsGiven = bench->count(gbl::cli::kLights.name) > 0;
        return gbl::runBenchLayouts(benchOptions);
    }

    editor.scenePath = scene;
    editor.vsync = !noVsync;
    if (!windowSize.empty()) {
        std::string error;
        auto const size = gbl::parseSize(windowSize, &error);
        if (!size) {
            std::fprintf(stderr, "gbuffer-lab: %s\n", error.c_str());
            return 2;
        }
        editor.width = size->width;
        editor.height = size->height;
        editor.sizeGiven = true;
    }
    if (editor.uiScale) {
        std::string error;
        if (!gbl::ui::parseUiScale(*editor.uiScale, "--ui-scale", &error)) {
            std::fprintf(stderr, "gbuffer-lab: %s.\n", error.c_str());
            return 2;
        }
    }
    if (editor.lightCount && (*editor.lightCount < 0 || *editor.lightCount > gbl::kMaxLights)) {
        std::fprintf(stderr, "gbuffer-lab: --lights must be between 0 and %d\n", gbl::kMaxLights);
        return 2;
    }
    return gbl::runEditor(editor);
}
