// The bench command's report: the table printed to the terminal and the JSON file.
#include "bench_results.h"

#include "core/frame_passes.h"
#include "pipeline_options.h"

#include <cmath>
#include <cstdio>
#include <map>

namespace gbl::bench {

using nlohmann::json;

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
    // forward+ keeps no G-buffer for its heat map to find the lit surfaces in, and prepass's thin one
    // is not counted over: their lit pixels and pairs are the scene's at that light count, taken
    // from a mode that measured them.
    auto const borrows = [](LightingMode m) { return m == LightingMode::ForwardPlus || m == LightingMode::Prepass; };
    for (auto& r : results) {
        if (!borrows(r.combo.mode) || r.framesMeasured == 0) continue;
        for (auto const& d : results)
            if (!shadesForward(d.combo.mode) && !borrows(d.combo.mode) && d.combo.lights == r.combo.lights &&
                d.combo.radiusScale == r.combo.radiusScale && d.lightPixelPairs && d.framesMeasured > 0) {
                r.litPixels = d.litPixels;
                r.lightPixelPairs = d.lightPixelPairs;
                break;
            }
        // prepass's light pass evaluates every light at every covered pixel, as quad's does: quad's count;
        // with volumes, the volume fragments, as volumes mode's with the same cull mode.
        bool const volumes = r.combo.prepassLights == PrepassLights::Volumes;
        if (r.combo.mode == LightingMode::Prepass)
            for (auto const& q : results)
                if (q.combo.mode == (volumes ? LightingMode::Volumes : LightingMode::Quad) &&
                    (!volumes || q.combo.cull == r.combo.cull) && q.combo.lights == r.combo.lights &&
                    q.combo.radiusScale == r.combo.radiusScale && q.evaluatedPairs && q.framesMeasured > 0) {
                    r.evaluatedPairs = q.evaluatedPairs;
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
    std::printf("%-22s %6s %6s %7s %11s %11s %9s %10s %10s %8s %9s %9s  %s\n", "mode", "lights", "radius", "frames",
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
        std::printf("%-22s %6d %6s %7d %11s %11s %9s %10s %10s %8d %9s %9s  %s%s%s\n", comboName(r.combo).c_str(),
                    r.combo.lights, radius, r.framesMeasured, ms(r.frameMs.median).c_str(), ms(r.frameMs.p95).c_str(),
                    speed.c_str(), formatCount(r.fragmentInvocations).c_str(),
                    formatCount(asDouble(r.litPixels)).c_str(), r.lightsShaded,
                    formatCount(asDouble(r.lightPixelPairs)).c_str(), formatCount(asDouble(r.evaluatedPairs)).c_str(),
                    r.status.c_str(), r.note.empty() ? "" : ": ", r.note.c_str());
        if (!r.passMs.empty()) {
            std::printf("%-22s", "");
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
    std::printf("%-22s %6s %9s %10s %10s %11s %9s\n", "mode", "lights", "ns/pair", "eval/lit", "vs quad", "floor ms",
                "vs floor");
    for (auto const& r : results) {
        if (!std::isfinite(r.pairs.nsPerEvaluated)) continue;
        std::printf("%-22s %6d %9.2f %10.2f %10.2f %11.1f %9.2f\n", comboName(r.combo).c_str(), r.combo.lights,
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
        if (r.combo.mode == LightingMode::Prepass)
            j["prepass_lights"] = enumName(kPrepassLightsNames, r.combo.prepassLights);
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

}  // namespace gbl::bench
