// `gbuffer-lab render`: one frame rendered headlessly, every intermediate image written to disk.
#pragma once

#include "core/pipeline_settings.h"
#include "pipeline_options.h"
#include "scene_setup.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gbl {

struct RenderOptions {
    std::string outDir;
    std::string size = "1280x720";
    std::optional<int> lights;
    float time = 0.0f;
    // Every pipeline field's value as its option gives it (--mode, --depth-copy, --exposure, ...), in
    // pipelineFields() order (app/pipeline_options.h); PipelineSettings{}'s when not given.
    std::vector<std::string> pipeline = defaultPipelineText();
    std::vector<std::string> views;  // extra debug views written as view_<name>.png
    std::optional<std::string> scene;
    std::optional<int> camera;  // view from the scene file's camera N (SceneData::cameras)
    bool allowOutsideUris = false;
    bool glass = false;  // the default scene's glass panes
    std::string glLimit;
    std::optional<std::string> sessionPath;      // render the frame a session file describes
    std::optional<std::string> saveSessionPath;  // write the session that reproduces this frame
    std::optional<int> accumulate;               // shade with the first K lights only
    bool contribution = false;                   // with --accumulate K: light K alone, no ambient
    std::optional<std::string> until;            // stop after this pass (core/frame_passes.h names)
    std::set<std::string> given;                 // options given explicitly (they override a session)
    std::optional<std::string> lesson;           // render a lesson step instead (app/lesson_command.cpp)
    std::optional<std::string> lessonsDir;
    // A frame estimated above this many seconds (core/frame_cost.h) is announced before it starts,
    // with the mode that gives the same image sooner.
    double warnSeconds = 5.0;
    // Re-light this G-buffer (a manifest or a `render --out` folder, docs/import.md) instead of
    // drawing a scene (app/relight_command.cpp).
    std::optional<std::string> gbuffer;
};

void addRenderOptions(CLI::App& sub, RenderOptions& options);
// Returns the process exit code: 0 on success, 2 for bad arguments or unwritable output, 1 when
// no GL context can be had.
int runRender(RenderOptions const& options);

// The frame settings of the pipeline options (--mode, --cull, --depth-copy, ...); nullopt with the
// one-sentence error in `error` when one is not a value of its field.
std::optional<PipelineSettings> renderSettings(RenderOptions const& options, std::string* error);
// Creates `dir` and checks it can be written into; the error otherwise.
std::optional<std::string> prepareOutDir(std::string const& dir);
// `render --gbuffer MANIFEST --out DIR` (app/relight_command.cpp).
int runRenderImported(RenderOptions const& options);

}  // namespace gbl
