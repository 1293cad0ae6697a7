// The headless render command.
#include "render_command.h"
#include "cli_options.h"

#include "cli_values.h"
#include "frame_export.h"
#include "lesson_command.h"
#include "long_frame.h"
#include "session_cli.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace gbl {

namespace fs = std::filesystem;

namespace {

int badArgument(std::string const& message) {
    std::fprintf(stderr, "gbuffer-lab render: %s\n", message.c_str());
    return 2;
}

}  // namespace

std::optional<std::string> prepareOutDir(std::string const& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) return "cannot create output directory " + dir + ": " + ec.message();
    fs::path const probe = fs::path(dir) / ".gbuffer-lab-write-test";
    std::ofstream f(probe);
    if (!f) return "output directory " + dir + " is not writable";
    f.close();
    fs::remove(probe, ec);
    return std::nullopt;
}

std::optional<PipelineSettings> renderSettings(RenderOptions const& o, std::string* error) {
    return pipelineFromText(o.pipeline, error);
}

void addRenderOptions(CLI::App& sub, RenderOptions& o) {
    cli::addShared(sub, cli::kOut, o.outDir)->required();
    cli::addShared(sub, cli::kSize, o.size)->capture_default_str();
    cli::addShared(sub, cli::kLights, o.lights);
    sub.add_option("--time", o.time, "Seconds of light animation")->capture_default_str();
    addPipelineOptions(sub, o.pipeline);  // --mode, --cull, --depth-copy, ... (core/pipeline_fields.h)
    sub.add_option("--view", o.views,
                   "Extra debug view(s) to write as view_NAME.png (position, depth and depth_linear with the 1-99 % "
                   "range of the drawn pixels; the EXRs hold the values)");
    cli::addShared(sub, cli::kScene, o.scene);
    sub.add_flag("--glass", o.glass,
                 "Stand three coloured glass panes in the default scene's courtyard (blended: drawn by the forward "
                 "pass after lighting)");
    sub.add_option("--camera", o.camera,
                   "View from the glTF file's camera N (0, 1, ... as the editor's View menu lists them)");
    cli::addShared(sub, cli::kAllowOutsideUris, o.allowOutsideUris);
    cli::addShared(sub, cli::kGl, o.glLimit);
    cli::addShared(sub, cli::kSession, o.sessionPath);
    sub.add_option("--save-session", o.saveSessionPath, "Also write the session that reproduces this frame");
    cli::addShared(sub, cli::kLesson, o.lesson);
    cli::addShared(sub, cli::kLessonsDir, o.lessonsDir);
    sub.add_option("--accumulate", o.accumulate,
                   "Shade with the first K lights only (0 = ambient alone) and outline light K's volume");
    sub.add_flag("--contribution", o.contribution, "With --accumulate K: light K alone, without ambient");
    sub.add_option("--warn-seconds", o.warnSeconds,
                   "Say so before a frame estimated to take longer than this, with a faster mode")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    sub.add_option("--gbuffer", o.gbuffer,
                   "Re-light another program's G-buffer (a manifest, or a `render --out` folder) instead of a scene");
    sub.add_option("--until", o.until,
                   "Stop after pass PASS (e.g. geometry, lighting, depth_copy) and write the frame as it stands");
    sub.parse_complete_callback([&sub, &o] {
        for (char const* name : {cli::kScene.name, cli::kLights.name, "--time", cli::kSize.name, cli::kSession.name,
                                 "--camera", "--glass"})
            if (sub.count(name) > 0) o.given.insert(name);
        notePipelineOptionsGiven(sub, o.given);
    });
}

namespace {

// Says so before a frame estimated above `warnSeconds` (core/frame_cost.h), with the faster mode;
// the frame is rendered as asked all the same.
void warnOfLongFrame(Renderer& renderer, FrameInput const& input, double warnSeconds) {
    auto const w = longFrameWarning(renderer, input, warnSeconds);
    if (!w) return;
    std::string const hint =
        w->cheaper ? " (--mode " + std::string(kLightingModeNames[std::size_t(w->cheaper->mode)]) + ")" : "";
    std::fprintf(stderr, "gbuffer-lab render: %s%s; rendering it as asked\n", w->message.c_str(), hint.c_str());
}

}  // namespace

int runRender(RenderOptions const& o) {
    if (o.gbuffer) return runRenderImported(o);
    if (o.lesson) return runRenderLesson(o);
    std::string error;
    auto const size = parseSize(o.size, &error);
    if (!size) return badArgument(error);
    if (o.lights && *o.lights < 0) return badArgument("--lights must be 0 or more, got " + std::to_string(*o.lights));
    if (o.contribution && !o.accumulate) return badArgument("--contribution needs --accumulate K");
    if (o.accumulate && (*o.accumulate < 0 || (o.contribution && *o.accumulate < 1)))
        return badArgument(std::string("--accumulate must be ") + (o.contribution ? "1" : "0") + " or more, got " +
                           std::to_string(*o.accumulate));
    if (o.lights && *o.lights > kMaxLights)
        return badArgument("--lights is limited to " + std::to_string(kMaxLights) + ", got " +
                           std::to_string(*o.lights));
    auto const parsed = renderSettings(o, &error);
    if (!parsed) return badArgument(error);
    PipelineSettings settings = *parsed;
    std::vector<DebugView> views;
    for (auto const& name : o.views) {
        auto v = enumFromName<DebugView>(kDebugViewNames, name);
        if (!v) {
            std::string known;
            for (std::string_view n : kDebugViewNames) known += (known.empty() ? "" : ", ") + std::string(n);
            return badArgument("--view '" + name + "' is not one of " + known);
        }
        views.push_back(*v);
    }
    if (auto err = prepareOutDir(o.outDir)) return badArgument(*err);
    if (o.saveSessionPath) {
        // Refuse before rendering rather than after a long frame (the write itself is checked too).
        fs::path const dir = fs::path(*o.saveSessionPath).parent_path();
        std::error_code ec;
        if (!dir.empty() && !fs::is_directory(dir, ec))
            return badArgument("cannot write " + *o.saveSessionPath + ": folder " + dir.string() + " does not exist");
    }

    if (o.glass && o.scene)
        return badArgument("--glass stands its panes in the default scene and cannot be combined with --scene " +
                           *o.scene);
    SceneRequest request{o.scene, o.lights, o.time, o.allowOutsideUris, o.glass};
    std::optional<PreparedScene> prepared;
    std::optional<ui::Session> session;  // the loaded session, with the overrides applied
    if (o.sessionPath) {
        // The session names its scene and lights; options that change the frame override it.
        if (o.given.count(cli::kScene.name) || o.given.count(cli::kLights.name) || o.glass)
            return badArgument(
                "--scene, --lights and --glass cannot be combined with --session (the session names "
                "its scene and lights)");
        ui::SessionLoad loaded = ui::loadSession(*o.sessionPath);
        if (!loaded.session) return badArgument(loaded.error);
        session = std::move(loaded.session);
        if (o.given.count("--time")) session->animation.time = o.time;
        PipelineSettings const fromOptions = settings;
        settings = session->pipeline;
        applyGivenOptions(settings, fromOptions, o.given);
        session->pipeline = settings;
        prepared = prepareSessionScene(*session, *o.sessionPath, o.allowOutsideUris, &error);
        if (!prepared) return badArgument(error);
    } else {
        prepared = prepareScene(request, &error);
        if (!prepared) return badArgument(error);
    }

    if (o.camera) {
        std::size_t const count = prepared->scene.cameras.size();
        if (*o.camera < 0 || std::size_t(*o.camera) >= count)
            return badArgument("--camera " + std::to_string(*o.camera) + " does not exist: the scene has " +
                               std::to_string(count) + (count == 1 ? " camera" : " cameras") +
                               (count ? " (0 to " + std::to_string(count - 1) + ")" : std::string()));
        prepared->camera = prepared->scene.cameras[std::size_t(*o.camera)].camera;
    }

    auto headless = createHeadlessRenderer(size->width, size->height, o.glLimit, &error);
    if (!headless) {
        std::fprintf(stderr, "gbuffer-lab render: %s\n", error.c_str());
        return 1;
    }
    Renderer& renderer = *headless->renderer;
    if (auto const why = renderer.modeUnavailable(settings.mode)) return badArgument(*why);
    if (auto err = renderer.setScene(prepared->scene)) return badArgument(*err);

    if (o.accumulate && *o.accumulate > int(prepared->lights.size()))
        return badArgument("--accumulate " + std::to_string(*o.accumulate) + " is more than the scene's " +
                           std::to_string(prepared->lights.size()) + " lights");
    FrameInput input{prepared->camera, prepared->lights, settings, true};
    input.accumulateLights = o.accumulate;
    input.lightContribution = o.contribution;
    warnOfLongFrame(renderer, input, o.warnSeconds);
    if (o.until) {
        // Checked against the passes this frame runs (its mode, depth copy, accumulation, overlays).
        if (auto why = stopAfterError(*o.until, renderer.framePasses(input))) return badArgument("--until " + *why);
        input.stopAfter = passFromName(*o.until);
    }
    FrameStats const stats = renderer.render(input);

    FrameExport frame{prepared->camera, prepared->lights, settings, stats, prepared->scene.triangleCount(), views};
    if (auto err = exportFrame(renderer, frame, o.outDir)) return badArgument(*err);
    if (o.saveSessionPath) {
        ui::Session const toSave = session ? *session : sessionFromCommandLine(request, *prepared, settings);
        if (auto e = ui::saveSession(*o.saveSessionPath, toSave)) return badArgument(*e);
    }
    std::string accumulated;
    if (o.accumulate)
        accumulated = o.contribution ? ", light " + std::to_string(*o.accumulate) + " alone"
                                     : ", first " + std::to_string(*o.accumulate) + " accumulated";
    if (stats.stoppedAfter) accumulated += ", stopped after " + std::string(passName(*stats.stoppedAfter));
    std::printf("wrote %s (%dx%d, %d lights%s, %.2f GPU ms, %llu GL errors)\n", o.outDir.c_str(), size->width,
                size->height, stats.lightsSubmitted, accumulated.c_str(), stats.gpuFrameMs,
                (unsigned long long)renderer.glErrorCount());
    return 0;
}

}  // namespace gbl
