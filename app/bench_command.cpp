// The headless bench command: every (mode, cull, light count) combination timed on the GPU.
#include "bench_command.h"
#include "bench_results.h"
#include "cli_options.h"

#include "cli_values.h"
#include "core/frame_passes.h"
#include "core/light_math.h"
#include "core/pipeline_settings.h"
#include "core/point_light.h"
#include "pipeline_options.h"
#include "renderer.h"
#include "scene_setup.h"
#include "session_cli.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <span>

namespace gbl {

using nlohmann::json;

using namespace bench;

namespace {

struct Coverage {
    std::uint64_t litPixels = 0;  // pixels some light reached
    std::uint64_t pairs = 0;      // (light, pixel) pairs where the light reached the surface
    std::uint64_t evaluated = 0;  // (light, pixel) pairs the mode evaluated
};

Coverage readCoverage(Renderer& renderer) {
    std::vector<float> const rg = renderer.readAttachment(Attachment::Coverage).pixels;  // x evaluated, y lit
    Coverage c;
    for (std::size_t i = 0; i < rg.size(); i += 2) {
        c.evaluated += std::uint64_t(rg[i]);
        c.pairs += std::uint64_t(rg[i + 1]);
        c.litPixels += rg[i + 1] > 0.0f;
    }
    return c;
}

Summary summarize(std::vector<double> const& v) {
    return {percentile(v, 0.5), percentile(v, 0.95)};
}

std::string comboName(Combination const& c) {
    std::string s(enumName(kLightingModeNames, c.mode));
    if (c.mode == LightingMode::Prepass && c.prepassLights != PrepassLights::Quad)
        s += "/" + std::string(enumName(kPrepassLightsNames, c.prepassLights));
    if (c.usesCull) s += "/" + std::string(enumName(kCullModeNames, c.cull));
    return s;
}

// Frame time of the last measured light count of the same mode, scaled linearly to `lights`:
// an upper bound for modes whose cost grows at most linearly with the light count, used to skip
// combinations that could not finish even one frame within the budget.
std::optional<double> predictedFrameSeconds(std::vector<Result> const& done, Combination const& c) {
    for (auto it = done.rbegin(); it != done.rend(); ++it) {
        Combination const& p = it->combo;
        if (p.mode != c.mode || p.cull != c.cull || p.prepassLights != c.prepassLights || it->framesMeasured == 0 ||
            p.lights <= 0)
            continue;
        return it->frameMs.median * 1e-3 * double(std::max(c.lights, 1)) / double(p.lights);
    }
    return std::nullopt;
}

Result runCombination(Renderer& renderer, Camera const& camera, std::span<PointLight const> lights,
                      PipelineSettings const& base, Combination const& c, BenchOptions const& o,
                      std::vector<Result> const& done) {
    Result r;
    r.combo = c;
    if (auto const why = renderer.modeUnavailable(c.mode)) {
        r.status = "unavailable";
        r.note = *why;
        return r;
    }
    bool const everyLight = c.mode == LightingMode::Quad || c.mode == LightingMode::Forward ||
                            (c.mode == LightingMode::Prepass && c.prepassLights == PrepassLights::Quad);
    if (everyLight && c.lights > kEveryLightModesMaxLights) {
        r.status = "unavailable";
        r.note = std::string(enumName(kLightingModeNames, c.mode)) +
                 " shades every light at every pixel; bench runs it up to " +
                 std::to_string(kEveryLightModesMaxLights) + " lights";
        return r;
    }
    if (auto const predicted = predictedFrameSeconds(done, c); predicted && *predicted > o.budgetSeconds) {
        char buf[160];
        std::snprintf(buf, sizeof buf,
                      "predicted %.1f s per frame from the previous light count, over the %.0f s budget", *predicted,
                      o.budgetSeconds);
        r.status = "skipped";
        r.note = buf;
        return r;
    }

    PipelineSettings settings = base;
    settings.mode = c.mode;
    settings.cull = c.cull;
    settings.prepassLights = c.prepassLights;
    FrameInput const input{camera, lights, settings, true};

    using Clock = std::chrono::steady_clock;
    auto const start = Clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
    double slowest = 0.0;
    std::vector<double> frame, fragments;
    std::map<std::string, std::vector<double>> perPass;
    std::vector<std::string> passOrder;
    int const total = o.warmup + o.frames;
    for (int i = 0; i < total; ++i) {
        if (i > 0 && !frameFitsBudget(elapsed(), slowest, o.budgetSeconds)) break;
        auto const t0 = Clock::now();
        FrameStats const s = renderer.render(input);
        slowest = std::max(slowest, std::chrono::duration<double>(Clock::now() - t0).count());
        r.glErrors += s.glErrors;
        r.lightsShaded = s.lightsShaded;
        r.timing = s.timingSource;
        r.timingReason = s.timingReason;
        if (i < o.warmup) continue;
        frame.push_back(s.gpuFrameMs);
        if (s.fragmentInvocations) fragments.push_back(double(*s.fragmentInvocations));
        for (PassTiming const& p : s.passes) {
            auto& samples = perPass[p.name];
            if (samples.empty()) passOrder.push_back(p.name);
            samples.push_back(p.gpuMs);
        }
    }
    r.framesMeasured = int(frame.size());
    // One more frame, untimed, with the heat map: its coverage counts give the lit pixels and
    // the (light, pixel) pairs (renderer/passes/coverage.h). It runs even past the budget, which
    // bounds the measured frames: without it no per-pair cost can be given.
    if (r.framesMeasured > 0) {
        FrameInput counted = input;
        counted.settings.view = DebugView::Heatmap;
        r.glErrors += renderer.render(counted).glErrors;
        Coverage const c = readCoverage(renderer);
        r.litPixels = c.litPixels;
        r.lightPixelPairs = c.pairs;
        r.evaluatedPairs = c.evaluated;
    }
    r.wallSeconds = elapsed();
    if (r.framesMeasured < o.frames) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "%d of %d frames fit in the %.0f s budget (slowest frame %.2f s)",
                      r.framesMeasured, o.frames, o.budgetSeconds, slowest);
        r.status = "over budget";
        r.note = buf;
    }
    if (!frame.empty()) r.frameMs = summarize(frame);
    for (auto const& name : passOrder) r.passMs.emplace_back(name, summarize(perPass[name]));
    if (!fragments.empty()) r.fragmentInvocations = percentile(fragments, 0.5);
    return r;
}

}  // namespace

void addBenchOptions(CLI::App& sub, BenchOptions& o) {
    cli::addShared(sub, cli::kSize, o.size)->capture_default_str();
    cli::addShared(sub, cli::kLights, o.lights)->delimiter(',')->capture_default_str();
    // Each value of a list is checked against its field's names (core/pipeline_fields.h).
    if (o.culls.empty()) o.culls = {std::string(enumName(kCullModeNames, PipelineSettings{}.cull))};
    sub.add_option("--modes", o.modes, "Lighting modes, comma-separated")
        ->delimiter(',')
        ->check(fieldValidator(*findPipelineField("mode")))
        ->capture_default_str();
    sub.add_option("--cull", o.culls, "Cull modes measured for volumes, comma-separated")
        ->delimiter(',')
        ->check(fieldValidator(*findPipelineField("cull")))
        ->capture_default_str();
    if (o.prepassLights.empty())
        o.prepassLights = {std::string(enumName(kPrepassLightsNames, PipelineSettings{}.prepassLights))};
    sub.add_option("--prepass-lights", o.prepassLights,
                   "prepass's light passes measured, comma-separated (volumes: with each --cull)")
        ->delimiter(',')
        ->check(fieldValidator(*findPipelineField("prepass_lights")))
        ->capture_default_str();
    sub.add_option("--frames", o.frames, "Measured frames per combination")->capture_default_str();
    sub.add_option("--warmup", o.warmup, "Warm-up frames per combination, not measured")->capture_default_str();
    sub.add_option("--budget", o.budgetSeconds, "Wall-clock seconds allowed per combination")->capture_default_str();
    sub.add_option("--radius-scale", o.radiusScale, "Scale every light's radius: a number, or auto = sqrt(32 / lights)")
        ->capture_default_str();
    sub.add_option("--json", o.jsonPath, "Also write the results to this JSON file");
    cli::addShared(sub, cli::kSession, o.sessionPath);
    cli::addShared(sub, cli::kScene, o.scenePath);
    cli::addShared(sub, cli::kGl, o.glLimit);
    sub.add_option("--layouts", o.layouts, "G-buffer layouts, comma-separated")
        ->delimiter(',')
        ->check(fieldValidator(*findPipelineField("layout")));
}

int runBench(BenchOptions const& o) {
    std::string error;
    auto const size = parseSize(o.size, &error);
    if (!size) return benchBadArgument(error);
    if (o.lights.empty()) return benchBadArgument("--lights needs at least one count");
    for (int n : o.lights)
        if (n < 0 || n > kMaxLights)
            return benchBadArgument("--lights counts must be 0.." + std::to_string(kMaxLights) + ", got " +
                                    std::to_string(n));
    auto const modeList = choiceList<LightingMode>(*findPipelineField("mode"), o.modes, "--modes", &error);
    if (!modeList) return benchBadArgument(error);
    auto const cullList = choiceList<CullMode>(*findPipelineField("cull"), o.culls, "--cull", &error);
    if (!cullList) return benchBadArgument(error);
    auto const prepassList =
        choiceList<PrepassLights>(*findPipelineField("prepass_lights"), o.prepassLights, "--prepass-lights", &error);
    if (!prepassList) return benchBadArgument(error);
    if (prepassList->empty()) return benchBadArgument("--prepass-lights needs at least one value");
    std::vector<LightingMode> const& modes = *modeList;
    std::vector<CullMode> const& culls = *cullList;
    if (modes.empty() || culls.empty()) return benchBadArgument("--modes and --cull need at least one value each");
    if (o.frames < 1) return benchBadArgument("--frames must be at least 1, got " + std::to_string(o.frames));
    if (o.warmup < 0) return benchBadArgument("--warmup must be 0 or more, got " + std::to_string(o.warmup));
    if (!(o.budgetSeconds > 0)) return benchBadArgument("--budget must be a positive number of seconds");
    bool const autoScale = o.radiusScale == "auto";
    float fixedScale = 1.0f;
    if (!autoScale) {
        char* end = nullptr;
        fixedScale = std::strtof(o.radiusScale.c_str(), &end);
        if (end == o.radiusScale.c_str() || *end != '\0' || !(fixedScale > 0.0f) || !std::isfinite(fixedScale))
            return benchBadArgument("--radius-scale must be a positive number or auto, got '" + o.radiusScale + "'");
    }
    if (o.jsonPath) {
        // Fail now rather than after minutes of measuring.
        std::ofstream probe(*o.jsonPath, std::ios::app);
        if (!probe) return benchBadArgument("cannot write the JSON file " + *o.jsonPath);
    }

    std::vector<int> counts = o.lights;
    std::optional<PreparedScene> prepared;
    PipelineSettings base;
    if (o.scenePath && o.sessionPath)
        return benchBadArgument("--scene and --session cannot be combined: the session names its scene");
    if (o.sessionPath) {
        ui::SessionLoad loaded = ui::loadSession(*o.sessionPath);
        if (!loaded.session) return benchBadArgument(loaded.error);
        prepared = prepareSessionScene(*loaded.session, *o.sessionPath, false, &error);
        if (!prepared) return benchBadArgument(error);
        base = loaded.session->pipeline;
        int const available = int(prepared->lights.size());
        if (!o.lightsGiven) counts = {available};
        for (int n : counts)
            if (n > available)
                return benchBadArgument("--lights " + std::to_string(n) + " is more than the " +
                                        std::to_string(available) + " lights of " + *o.sessionPath);
    } else {
        SceneRequest request;
        request.scenePath = o.scenePath;
        request.lightCount = *std::max_element(counts.begin(), counts.end());
        prepared = prepareScene(request, &error);
        if (!prepared) return benchBadArgument(error);
        int const available = int(prepared->lights.size());
        if (o.scenePath && !o.lightsGiven) counts = {available};
        for (int n : counts)
            if (n > available)
                return benchBadArgument("--lights " + std::to_string(n) + " is more than the " +
                                        std::to_string(available) + " lights of the scene");
    }
    if (!o.layouts.empty())
        if (auto layout = enumFromName<GBufferLayout>(kGBufferLayoutNames, o.layouts.front())) base.layout = *layout;
    auto headless = createHeadlessRenderer(size->width, size->height, o.glLimit, &error);
    if (!headless) {
        std::fprintf(stderr, "gbuffer-lab bench: %s\n", error.c_str());
        return 1;
    }
    Renderer& renderer = *headless->renderer;
    if (auto err = renderer.setScene(prepared->scene)) return benchBadArgument(*err);

    std::vector<Result> results;
    for (int n : counts) {
        // The default scene's lights do not depend on the count: n lights are a prefix of more.
        std::vector<PointLight> scaled(prepared->lights.begin(), prepared->lights.begin() + n);
        float const scale = autoScale ? (n > 32 ? std::sqrt(32.0f / float(n)) : 1.0f) : fixedScale;
        if (scale != 1.0f)
            for (auto& l : scaled) l = scaleLightFalloff(l, scale);
        std::span<PointLight const> const lights(scaled);
        for (LightingMode m : modes) {
            std::vector<PrepassLights> const lightPasses =
                m == LightingMode::Prepass ? *prepassList : std::vector<PrepassLights>{PrepassLights::Quad};
            for (PrepassLights const lightPass : lightPasses) {
                PipelineSettings s;
                s.mode = m;
                s.prepassLights = lightPass;
                bool const usesCull = drawsLightVolumes(s);
                for (std::size_t ci = 0; ci < (usesCull ? culls.size() : 1); ++ci) {
                    Combination const c{m, usesCull ? culls[ci] : CullMode::Front, usesCull, n, scale, lightPass};
                    std::fprintf(stderr, "bench: %s with %d lights...\n", comboName(c).c_str(), n);
                    results.push_back(runCombination(renderer, prepared->camera, lights, base, c, o, results));
                }
            }
        }
    }

    fillPairCosts(results);
    printTable(results, renderer.caps(), *size, o);
    if (o.jsonPath) {
        std::ofstream f(*o.jsonPath, std::ios::trunc);
        f << toJson(results, renderer.caps(), *size, o).dump(2) << "\n";
        if (!f) return benchBadArgument("cannot write the JSON file " + *o.jsonPath);
    }
    return 0;
}

}  // namespace gbl
