#include "editor_cli.h"

#include "cli_options.h"
#include "cli_values.h"
#include "core/point_light.h"
#include "model/ui_scale.h"

#include <cstdio>

namespace gbl {

void addEditorOptions(CLI::App& app, EditorCli& cli) {
    EditorOptions& editor = cli.editor;
    app.add_option("scene", cli.scene, "A glTF 2.0 file (.gltf or .glb) to open instead of the default scene");
    app.add_option("--screenshot", editor.screenshotPath,
                   "Write the editor window as PNG after --frames frames, then exit");
    app.add_option("--frames", editor.frames, "Frames to run before exiting (0: until the window is closed)");
    cli::addShared(app, cli::kSize, cli.windowSize);
    cli::addShared(app, cli::kLights, editor.lightCount);
    app.add_flag("--glass", editor.glass,
                 "Stand three coloured glass panes in the default scene's courtyard (drawn forward after lighting)");
    cli::addShared(app, cli::kSession, editor.sessionPath);
    app.add_option("--gbuffer", editor.gbufferPath,
                   "Open another program's G-buffer (a manifest, a folder holding one, or a `render --out` folder) "
                   "and re-light it live (docs/import.md)");
    app.add_option("--ui-test", editor.uiTestScript, "Run a UI test script and exit 0 when every check passes");
    cli::addShared(app, cli::kGl, editor.glLimit);
    app.add_flag("--no-vsync", cli.noVsync, "Render as fast as possible");
    cli::addShared(app, cli::kAllowOutsideUris, editor.allowOutsideUris);
    app.add_option("--log-frames", editor.logFramesPath,
                   "Write one JSON line per frame to FILE: rendered or not, frame ms, camera, selection, input events");
    app.add_option("--frame-sleep-ms", editor.frameSleepMs,
                   "Sleep this long every frame, still taking input (tests of slow machines)")
        ->check(CLI::Range(0, 10000));
    cli::addShared(app, cli::kLesson, editor.lesson);
    app.add_option("--frame-warn-seconds", editor.frameWarnSeconds,
                   "Switch to a faster mode, with a message, before a frame estimated to take longer than this")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--ui-scale", editor.uiScale,
                   "Scale text and controls, 0.75 to 3 (1.5 for a projector); kept with the window layout otherwise");
    app.add_flag("--continuous", editor.continuousRender,
                 "Run the renderer every frame even when nothing changed (for timing)");
}

std::optional<int> finishEditorOptions(EditorCli& cli) {
    EditorOptions& editor = cli.editor;
    editor.scenePath = cli.scene;
    editor.vsync = !cli.noVsync;
    if (!cli.windowSize.empty()) {
        std::string error;
        auto const size = parseSize(cli.windowSize, &error);
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
        if (!ui::parseUiScale(*editor.uiScale, "--ui-scale", &error)) {
            std::fprintf(stderr, "gbuffer-lab: %s.\n", error.c_str());
            return 2;
        }
    }
    if (editor.lightCount && (*editor.lightCount < 0 || *editor.lightCount > kMaxLights)) {
        std::fprintf(stderr, "gbuffer-lab: --lights must be between 0 and %d\n", kMaxLights);
        return 2;
    }
    return std::nullopt;
}

}  // namespace gbl
