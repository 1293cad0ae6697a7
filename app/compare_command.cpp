// The compare command: render each session like `render --session`, then diff the lit frames.
#include "compare_command.h"
#include "cli_options.h"

#include "cli_values.h"
#include "frame_export.h"
#include "image/image_io.h"
#include "model/image_stats.h"
#include "model/viewer_tools.h"
#include "session_cli.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace gbl {

namespace fs = std::filesystem;
using ordered_json = nlohmann::ordered_json;

namespace {

int badArgument(std::string const& message) {
    std::fprintf(stderr, "gbuffer-lab compare: %s\n", message.c_str());
    return 2;
}

struct Side {
    ui::Session session;
    PreparedScene prepared;
    PipelineSettings settings;
    FrameStats stats;
    FloatImage lighting;
};

std::optional<std::string> loadSide(std::string const& path, bool allowOutsideUris, Side& side) {
    ui::SessionLoad loaded = ui::loadSession(path);
    if (!loaded.session) return loaded.error;
    side.session = std::move(*loaded.session);
    std::string error;
    auto prepared = prepareSessionScene(side.session, path, allowOutsideUris, &error);
    if (!prepared) return error;
    side.prepared = std::move(*prepared);
    side.settings = side.session.pipeline;
    return std::nullopt;
}

ordered_json passTimes(FrameStats const& stats) {
    ordered_json j = ordered_json::object();
    for (auto const& p : stats.passes) j[p.name] = p.gpuMs;
    j["total"] = stats.gpuFrameMs;
    return j;
}

}  // namespace

void addCompareOptions(CLI::App& sub, CompareOptions& o) {
    sub.add_option("a", o.sessionA, "Session file of side A")->required();
    sub.add_option("b", o.sessionB, "Session file of side B")->required();
    cli::addShared(sub, cli::kOut, o.outDir)->required();  // a/, b/, diff.exr, diff.png and compare.json
    cli::addShared(sub, cli::kSize, o.size)->capture_default_str();
    sub.add_option("--threshold", o.threshold, "A pixel differs when its largest RGB difference exceeds this")
        ->capture_default_str();
    cli::addShared(sub, cli::kAllowOutsideUris, o.allowOutsideUris);
}

int runCompare(CompareOptions const& o) {
    std::string error;
    auto const size = parseSize(o.size, &error);
    if (!size) return badArgument(error);
    if (!(o.threshold >= 0.0f)) return badArgument("--threshold must be 0 or more");
    Side a, b;
    if (auto e = loadSide(o.sessionA, o.allowOutsideUris, a)) return badArgument(*e);
    if (auto e = loadSide(o.sessionB, o.allowOutsideUris, b)) return badArgument(*e);
    // A diff of two different scenes measures nothing about the pipeline.
    if (a.session.scene != b.session.scene)
        return badArgument(o.sessionA + " and " + o.sessionB + " show different scenes (" + a.session.scene + " and " +
                           b.session.scene + "); compare needs the same scene on both sides");
    if (a.prepared.scene.triangleCount() != b.prepared.scene.triangleCount())
        return badArgument(o.sessionA + " and " + o.sessionB + " build scenes of different sizes (" +
                           std::to_string(a.prepared.scene.triangleCount()) + " and " +
                           std::to_string(b.prepared.scene.triangleCount()) + " triangles)");
    fs::path const out(o.outDir);
    std::error_code ec;
    for (char const* sub : {"a", "b"}) {
        fs::create_directories(out / sub, ec);
        if (ec) return badArgument("cannot create output directory " + (out / sub).string() + ": " + ec.message());
    }

    auto headless = createHeadlessRenderer(size->width, size->height, "", &error);
    if (!headless) {
        std::fprintf(stderr, "gbuffer-lab compare: %s\n", error.c_str());
        return 1;
    }
    Renderer& renderer = *headless->renderer;
    for (Side* side : {&a, &b}) {
        if (auto const why = renderer.modeUnavailable(side->settings.mode)) return badArgument(*why);
        if (auto err = renderer.setScene(side->prepared.scene)) return badArgument(*err);
        side->stats = renderer.render({side->prepared.camera, side->prepared.lights, side->settings, true});
        side->lighting = renderer.readAttachment(Attachment::Lighting);
        FrameExport frame{side->prepared.camera,
                          side->prepared.lights,
                          side->settings,
                          side->stats,
                          side->prepared.scene.triangleCount(),
                          {}};
        if (auto err = exportFrame(renderer, frame, (out / (side == &a ? "a" : "b")).string()))
            return badArgument(*err);
    }

    // The editor's diff (model/image_stats.h): B is the reference, as a pinned frame is.
    ui::DiffStats const d = ui::diffImages(a.lighting, b.lighting, 0x7, o.threshold);
    ui::DiffStats const rel = ui::diffImages(a.lighting, b.lighting, 0x7, o.threshold, ui::DiffMode::Relative);
    ui::ImageStats const sa = ui::imageStats(a.lighting, 0x7), sb = ui::imageStats(b.lighting, 0x7);
    if (auto e = writeExr((out / "diff.exr").string(), d.diff)) return badArgument(*e);
    // The heat map scaled to the largest difference (turbo), NaN/Inf magenta, as the viewport shows it.
    std::vector<std::uint8_t> const rgba = ui::diffHeatmap(d, d.max > 0.0f ? d.max : 1.0f);
    FloatImage heat;
    heat.width = d.diff.width;
    heat.height = d.diff.height;
    heat.channels = 4;
    heat.pixels.resize(rgba.size());
    for (std::size_t i = 0; i < rgba.size(); ++i) heat.pixels[i] = float(rgba[i]) / 255.0f;
    if (auto e = writePng((out / "diff.png").string(), heat, 3)) return badArgument(*e);

    ordered_json j;
    j["a"] = o.sessionA;
    j["b"] = o.sessionB;
    j["width"] = size->width;
    j["height"] = size->height;
    j["max_abs"] = d.max;
    j["max_at"] = {d.maxAt.x, d.maxAt.y};
    j["mean_abs"] = d.mean;
    j["max_rel"] = rel.max;
    j["pixels_differing"] = d.overThreshold;
    j["threshold"] = o.threshold;
    j["pixels"] = d.pixels;
    j["nan_a"] = sa.nanPixels;
    j["nan_b"] = sb.nanPixels;
    j["inf_a"] = sa.infPixels;
    j["inf_b"] = sb.infPixels;
    j["gpu_ms_a"] = passTimes(a.stats);
    j["gpu_ms_b"] = passTimes(b.stats);
    std::ofstream f(out / "compare.json");
    f << j.dump(2) << "\n";
    if (!f) return badArgument("cannot write " + (out / "compare.json").string());
    std::printf("compared %s with %s (%dx%d): max |A-B| %.4g at %d,%d, mean %.4g, %ld of %ld px over %.3g\n",
                o.sessionA.c_str(), o.sessionB.c_str(), size->width, size->height, d.max, d.maxAt.x, d.maxAt.y, d.mean,
                d.overThreshold, d.pixels, o.threshold);
    return 0;
}

}  // namespace gbl
