// The headless bench command: every (mode, cull, light count) combination timed on the GPU.
#include "bench_command.h"
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

namespace {

struct Combination {
    LightingMode mode = LightingMode::Quad;
    CullMode cull = CullMode::Front;
    bool usesCull = false;  // only `volumes` has a cull mode
    int lights = 0;
    float radiusScale = 1.0f;
};

struct Summary {
    double median = 0.0;
    double p95 = 0.0;
};

struct Result {
    Combination combo;
    std::string status = "ok";  // ok | over budget | skipped | unavailable
    std::string note;           // why, for anything but ok
    int framesMeasured = 0;
    double wallSeconds = 0.0;
    Summary frameMs;
    std::vector<std::pair<std::string, Summary>> passMs;  // in frame order
    std::optional<double> fragmentInvocations;            // median over measured frames
    std::optional<std::uint64_t> litPixels;
    std::optional<std::uint64_t> lightPixelPairs;
    std::optional<std::uint64_t> evaluatedPairs;
    int lightsShaded = 0;
    std::uint64_t glErrors = 0;
    std::string timing;  // how pass times were measured (FrameStats::timingSource)
    std::string timingReason;
    PairCost pairs;               // filled once every combination ran (quad's cost is the reference)
    int quadReferenceLights = 0;  // light count of the quad figure used, 0 for none
};

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
    if (c.usesCull) s += "/" + std::string(enumName(kCullModeNames, c.cull));
    return s;
}

// Frame time of the last measured light count of the same mode, scaled linearly to `lights`:
// an upper bound for modes whose cost grows at most linearly with the light count, used to skip
// combinations that could not finish even one frame within the budget.
std::optional<double> predictedFrameSeconds(std::vector<Result> const& done, Combination const& c) {
    for (auto it = done.rbegin(); it != done.rend(); ++it) {
        Combination const& p = it->combo;
        if (p.mode != c.mode || p.cull != c.cull || it->framesMeasured == 0 || p.lights <= 0) continue;
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
    if ((c.mode == LightingMode::Quad || c.mode == LightingMode::Forward) && c.lights > kEveryLightModesMaxLights) {
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

std::string formatCount(std::optional<double> v) {
    if (!v) return "-";
    char buf[32];
    if (*v >= 1e9)
        std::snprintf(buf, sizeof buf, "%.2fG", *v * 1e-9);
    else if (*v >= 1e6)
        std::snprintf(buf, sizeof buf, "%.2fM", *v * 1e-6);
    else if (*v >= 1e3)
        std::snprintf(buf, sizeof buf, "%.1fk", *v * 1e-3);
    else
        std::snprintf(buf, sizeof buf, "%.0f", *v);
    return buf;
}

std::optional<double> asDouble(std::optional<std::uint64_t> v) {
    return v ? std::optional<double>(double(*v)) : std::nullopt;
}

// The lighting work of a frame: the passes core/frame_passes.h counts as lighting (the lighting
// pass, the light lists, the volumes' depth copy, the split combine, or forward's shading pass).
double lightingMs(Result const& r) {
    double ms = 0.0;
    for (auto const& [name, s] : r.passMs)
        if (std::optional<PassId> const id = passFromName(name); id && countsAsLighting(*id)) ms += s.median;
    return ms;
}

// Per-pair costs for every result, against quad at the same light count or, where quad was not
// measured there (it refuses or runs over budget at large counts), the nearest count that has
// one: quad's cost per pair hardly depends on the count.
void fillPairCosts(std::vector<Result>& results) {
    // forward+ keeps no G-buffer for its heat map to find the lit surfaces in: its lit pixels and
    // pairs are the scene's at that light count, taken from a mode that measured them.
    for (auto& r : results) {
        if (r.combo.mode != LightingMode::ForwardPlus || r.framesMeasured == 0) continue;
        for (auto const& d : results)
            if (!shadesForward(d.combo.mode) && d.combo.lights == r.combo.lights &&
                d.combo.radiusScale == r.combo.radiusScale && d.lightPixelPairs && d.framesMeasured > 0) {
                r.litPixels = d.litPixels;
                r.lightPixelPairs = d.lightPixelPairs;
                break;
            }
    }
    for (auto& r : results) {
        if (r.framesMeasured == 0 || !r.evaluatedPairs || !r.lightPixelPairs) continue;
        Result const* quad = nullptr;
        for (auto const& q : results) {
            if (q.combo.mode != LightingMode::Quad || q.framesMeasured == 0 || !q.evaluatedPairs ||
                *q.evaluatedPairs == 0)
                continue;
            if (!quad || std::abs(q.combo.lights - r.combo.lights) < std::abs(quad->combo.lights - r.combo.lights))
                quad = &q;
        }
        double quadNs = std::nan("");
        if (quad) {
            quadNs = lightingMs(*quad) * 1e6 / double(*quad->evaluatedPairs);
            r.quadReferenceLights = quad->combo.lights;
        }
        r.pairs = pairCost({lightingMs(r), *r.evaluatedPairs, *r.lightPixelPairs}, quadNs);
    }
}

// The quad result with the same light count, for the speed-up column.
Result const* quadFor(std::vector<Result> const& results, int lights) {
    for (auto const& r : results)
        if (r.combo.mode == LightingMode::Quad && r.combo.lights == lights && r.framesMeasured > 0) return &r;
    return nullptr;
}

void printTable(std::vector<Result> const& results, GlCaps const& caps, Size2 size, BenchOptions const& o) {
    std::printf("gbuffer-lab bench: %dx%d, %s | %s | %s\n", size.width, size.height, caps.vendor.c_str(),
                caps.renderer.c_str(), caps.version.c_str());
    std::string timing;
    for (auto const& r : results)
        if (timing.empty()) timing = r.timingReason;
    std::printf(
        "%d warm-up + %d measured frames per combination, budget %.0f s each\npass times: %s\nlight loops: %s\n\n",
        o.warmup, o.frames, o.budgetSeconds, timing.c_str(), caps.lightLoopsNote().c_str());
    std::printf("%-16s %6s %6s %7s %11s %11s %9s %10s %10s %8s %9s %9s  %s\n", "mode", "lights", "radius", "frames",
                "frame med", "frame p95", "vs quad", "frag.inv", "lit px", "shaded", "lit pairs", "evaluated",
                "status");
    for (auto const& r : results) {
        std::string speed = "-";
        if (Result const* q = quadFor(results, r.combo.lights); q && r.framesMeasured > 0 && r.frameMs.median > 0) {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%.1fx", q->frameMs.median / r.frameMs.median);
            speed = buf;
        }
        auto ms = [&](double v) {
            char buf[32];
            if (r.framesMeasured == 0) return std::string("-");
            std::snprintf(buf, sizeof buf, "%.2f ms", v);
            return std::string(buf);
        };
        char radius[16];
        std::snprintf(radius, sizeof radius, "x%.3g", r.combo.radiusScale);
        std::printf("%-16s %6d %6s %7d %11s %11s %9s %10s %10s %8d %9s %9s  %s%s%s\n", comboName(r.combo).c_str(),
                    r.combo.lights, radius, r.framesMeasured, ms(r.frameMs.median).c_str(), ms(r.frameMs.p95).c_str(),
                    speed.c_str(), formatCount(r.fragmentInvocations).c_str(),
                    formatCount(asDouble(r.litPixels)).c_str(), r.lightsShaded,
                    formatCount(asDouble(r.lightPixelPairs)).c_str(), formatCount(asDouble(r.evaluatedPairs)).c_str(),
                    r.status.c_str(), r.note.empty() ? "" : ": ", r.note.c_str());
        if (!r.passMs.empty()) {
            std::printf("%-16s", "");
            for (auto const& [name, s] : r.passMs) std::printf("  %s %.2f/%.2f", name.c_str(), s.median, s.p95);
            std::printf("  (ms median/p95)\n");
        }
    }
    std::printf("\nfrag.inv: fragment-shader invocations of the lighting pass (ARB_pipeline_statistics_query%s).\n",
                caps.pipelineStatistics ? "" : ": unavailable on this context");
    std::printf(
        "frag.inv counts fragment shaders only: tiled shades in a compute shader, so it shows the lighting\n"
        "pass's 0 there. radius: the lights' radius scale (--radius-scale). lit px: pixels some light reached;\n"
        "lit pairs: (light, pixel) pairs where the light reached the surface; evaluated: (light, pixel) pairs the\n"
        "mode ran its shading for (volume fragments, tile-list entries, every light for quad). lit pairs /\n"
        "lit px is the least work per pixel any exact method needs; evaluated / lit pairs is the waste.\n");
    std::printf(
        "\nper-pair cost: lighting ms per evaluated light\u00b7pixel pair; work floor = lit pairs \u00d7 quad's ns "
        "per pair.\n");
    std::printf("%-16s %6s %9s %10s %10s %11s %9s\n", "mode", "lights", "ns/pair", "eval/lit", "vs quad", "floor ms",
                "vs floor");
    for (auto const& r : results) {
        if (!std::isfinite(r.pairs.nsPerEvaluated)) continue;
        std::printf("%-16s %6d %9.2f %10.2f %10.2f %11.1f %9.2f\n", comboName(r.combo).c_str(), r.combo.lights,
                    r.pairs.nsPerEvaluated, r.pairs.evaluatedPerLit, r.pairs.perPairVsQuad, r.pairs.floorMs,
                    r.pairs.vsFloor);
    }
    for (auto const& r : results) {
        if (!std::isfinite(r.pairs.nsPerEvaluated)) continue;
        std::string const ref = r.quadReferenceLights && r.quadReferenceLights != r.combo.lights
                                    ? " [quad cost from " + std::to_string(r.quadReferenceLights) + " lights]"
                                    : "";
        std::printf("%6d lights, %s%s\n", r.combo.lights, pairVerdict(comboName(r.combo), r.pairs).c_str(),
                    ref.c_str());
    }
}

// NaN is not JSON: absent figures are null.
json number(double v) {
    return std::isfinite(v) ? json(v) : json(nullptr);
}

json toJson(std::vector<Result> const& results, GlCaps const& caps, Size2 size, BenchOptions const& o) {
    std::string timing, timingReason;
    for (auto const& r : results)
        if (timing.empty()) timing = r.timing, timingReason = r.timingReason;
    json combos = json::array();
    for (auto const& r : results) {
        json passes = json::object();
        for (auto const& [name, s] : r.passMs) passes[name] = {{"median_ms", s.median}, {"p95_ms", s.p95}};
        json j = {{"mode", enumName(kLightingModeNames, r.combo.mode)},
                  {"lights", r.combo.lights},
                  {"radius_scale", r.combo.radiusScale},
                  {"status", r.status},
                  {"frames_measured", r.framesMeasured},
                  {"wall_seconds", r.wallSeconds},
                  {"lights_shaded", r.lightsShaded},
                  {"gl_errors", r.glErrors},
                  {"passes", passes}};
        if (r.combo.usesCull) j["cull"] = enumName(kCullModeNames, r.combo.cull);
        if (!r.note.empty()) j["note"] = r.note;
        if (r.framesMeasured > 0) j["frame"] = {{"median_ms", r.frameMs.median}, {"p95_ms", r.frameMs.p95}};
        if (r.fragmentInvocations) j["fragment_invocations"] = *r.fragmentInvocations;
        if (r.litPixels) j["lit_pixels"] = *r.litPixels;
        if (r.lightPixelPairs) j["light_pixel_pairs"] = *r.lightPixelPairs;
        if (r.evaluatedPairs) j["evaluated_light_pixel_pairs"] = *r.evaluatedPairs;
        if (std::isfinite(r.pairs.nsPerEvaluated))
            j["pair_cost"] = {{"lighting_ms", lightingMs(r)},
                              {"ns_per_evaluated_pair", number(r.pairs.nsPerEvaluated)},
                              {"evaluated_per_lit_pair", number(r.pairs.evaluatedPerLit)},
                              {"per_pair_vs_quad", number(r.pairs.perPairVsQuad)},
                              {"work_floor_ms", number(r.pairs.floorMs)},
                              {"vs_work_floor", number(r.pairs.vsFloor)},
                              {"quad_reference_lights", r.quadReferenceLights},
                              {"verdict", pairVerdict(comboName(r.combo), r.pairs)}};
        combos.push_back(j);
    }
    return {{"gl_vendor", caps.vendor},
            {"gl_renderer", caps.renderer},
            {"gl_version", caps.version},
            {"width", size.width},
            {"height", size.height},
            {"warmup_frames", o.warmup},
            {"frames", o.frames},
            {"budget_seconds", o.budgetSeconds},
            {"pipeline_statistics", caps.pipelineStatistics},
            {"masked_branches", caps.masksBranches},
            {"timing", timing},
            {"timing_reason", timingReason},
            {"combinations", combos}};
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
            bool const usesCull = m == LightingMode::Volumes;
            for (std::size_t ci = 0; ci < (usesCull ? culls.size() : 1); ++ci) {
                Combination const c{m, usesCull ? culls[ci] : CullMode::Front, usesCull, n, scale};
                std::fprintf(stderr, "bench: %s with %d lights...\n", comboName(c).c_str(), n);
                results.push_back(runCombination(renderer, prepared->camera, lights, base, c, o, results));
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
