// `gbuffer-lab bench`: GPU time per pass and per frame for each lighting mode and light count.
#pragma once

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace gbl {

// Prints "gbuffer-lab bench: <message>" and returns a bad argument's exit status (2).
inline int benchBadArgument(std::string const& message) {
    std::fprintf(stderr, "gbuffer-lab bench: %s\n", message.c_str());
    return 2;
}

struct BenchOptions {
    std::string size = "1280x720";
    std::vector<int> lights{32, 256, 1024, 4096};
    std::vector<std::string> modes{"quad", "volumes", "tiled", "clustered", "forward", "forward+", "prepass"};
    // Cull modes measured for `volumes` (each one is its own combination); other modes ignore it.
    // addBenchOptions starts it at PipelineSettings{}'s cull.
    std::vector<std::string> culls;
    // prepass's light passes measured (`prepass_lights`: quad, volumes); volumes runs each cull mode.
    // addBenchOptions starts it at PipelineSettings{}'s.
    std::vector<std::string> prepassLights;
    int frames = 20;            // measured frames per combination
    int warmup = 3;             // frames rendered and thrown away first (shader and cache warm-up)
    double budgetSeconds = 60;  // wall-clock budget per combination's warm-up and measured frames
    // Stretches every light's falloff (Kl / s, Kq / s^2) so radii scale by s: a number, or
    // "auto" for s = sqrt(32 / lights) when lights > 32, which keeps the lit area per light
    // count, and so the lights reaching each pixel, as in the 32-light default scene. 1 = the
    // default scene's lights unchanged. The default is auto: with fixed radii, every pixel is lit
    // by more lights as the count grows, which measures overdraw rather than light culling.
    std::string radiusScale = "auto";
    std::optional<std::string> jsonPath;
    // A session file: its scene, camera, lights and pipeline settings (mode and cull still come
    // from --modes/--cull). Without --lights the session's own light count is measured.
    std::optional<std::string> sessionPath;
    std::optional<std::string> scenePath;  // a glTF scene instead of the default one
    bool lightsGiven = false;              // --lights was on the command line
    std::string glLimit;                   // "3.3" pretends the context is at most that version
    // G-buffer layouts (bench_layouts.cpp loops over them); runBench measures the first, or the
    // session's / classic when empty.
    std::vector<std::string> layouts;
};

void addBenchOptions(CLI::App& sub, BenchOptions& options);

// Returns the process exit code: 0 when every combination ran (combinations over budget or
// unavailable on this context still count as run: they are reported), 2 for bad arguments or
// an unwritable JSON file, 1 when no GL context can be had.
int runBench(BenchOptions const& options);

// quad, forward and prepass shade every light at every pixel, so their frame grows with lights x pixels:
// above this many lights (the old light limit) bench refuses them rather than spend minutes on
// one frame. volumes, tiled and clustered cull, and run up to kMaxLights.
inline constexpr int kEveryLightModesMaxLights = 16384;

// --- statistics (pure; tests/bench_stats_test.cpp) ----------------------------------------

// Nearest-rank percentile: the smallest sample with at least p of the samples at or below it
// (p in (0, 1]); p = 0.5 is the lower median for even counts. NaN for no samples.
inline double percentile(std::vector<double> samples, double p) {
    if (samples.empty()) return std::nan("");
    std::sort(samples.begin(), samples.end());
    auto const rank = std::size_t(std::ceil(p * double(samples.size())));
    return samples[std::clamp<std::size_t>(rank, 1, samples.size()) - 1];
}

// Whether to start another frame: it must be expected to end within the budget, judged from the
// slowest frame so far (frames of one combination vary little; the slowest keeps the guess safe).
inline bool frameFitsBudget(double elapsedSeconds, double slowestFrameSeconds, double budgetSeconds) {
    return elapsedSeconds + slowestFrameSeconds <= budgetSeconds;
}

// --- per-pair cost (pure; tests/bench_stats_test.cpp) ---------------------------------------
//
// A mode's lighting pass does work per evaluated (light, pixel) pair: the coverage target's x,
// summed. The pairs that actually receive light (its y, summed) are what any exact method must
// evaluate; at the cheapest per-pair cost (quad's, which does nothing but shade) they are the
// work floor. A mode's distance from the floor splits into evaluating too many pairs
// (evaluated / lit) and paying more per pair (its ns per pair / quad's).

struct PairCounts {
    double lightingMs = 0.0;      // the lighting pass's median (list building included)
    std::uint64_t evaluated = 0;  // evaluated (light, pixel) pairs
    std::uint64_t lit = 0;        // (light, pixel) pairs where the light reached the surface
};

struct PairCost {
    double nsPerEvaluated = std::nan("");   // lightingMs per evaluated pair; NaN for none
    double evaluatedPerLit = std::nan("");  // 1 = ideal culling; NaN for no lit pairs
    double perPairVsQuad = std::nan("");    // nsPerEvaluated / quad's; NaN without quad
    double floorMs = std::nan("");          // lit pairs x quad's ns per pair
    double vsFloor = std::nan("");          // lightingMs / floorMs
};

// `quadNsPerPair`: quad's ns per evaluated pair (NaN when quad was not measured).
inline PairCost pairCost(PairCounts const& m, double quadNsPerPair) {
    PairCost c;
    if (m.evaluated > 0) c.nsPerEvaluated = m.lightingMs * 1e6 / double(m.evaluated);
    if (m.lit > 0) c.evaluatedPerLit = double(m.evaluated) / double(m.lit);
    if (quadNsPerPair > 0.0) {
        c.perPairVsQuad = c.nsPerEvaluated / quadNsPerPair;
        c.floorMs = double(m.lit) * quadNsPerPair * 1e-6;
        if (c.floorMs > 0.0) c.vsFloor = m.lightingMs / c.floorMs;
    }
    return c;
}

// The one line bench prints per mode, e.g. "volumes/front: 1.29x the ideal number of light.pixel
// evaluations, 3.1x the per-pair cost of quad, 4.0x the work floor (550 ms)".
inline std::string pairVerdict(std::string const& mode, PairCost const& c) {
    auto x = [](double v) {
        if (!std::isfinite(v)) return std::string("?");
        char buf[32];
        std::snprintf(buf, sizeof buf, v < 10 ? "%.2f" : "%.1f", v);
        return std::string(buf);
    };
    std::string s = mode + ": ";
    if (!std::isfinite(c.evaluatedPerLit)) return s + "no light reached a surface, nothing to compare";
    s += x(c.evaluatedPerLit) + "\u00d7 the ideal number of light\u00b7pixel evaluations, ";
    if (!std::isfinite(c.perPairVsQuad)) return s + x(c.nsPerEvaluated) + " ns per pair (no quad figure to compare)";
    s += x(c.perPairVsQuad) + "\u00d7 the per-pair cost of quad, " + x(c.vsFloor) + "\u00d7 the work floor (" +
         x(c.floorMs) + " ms)";
    return s;
}

}  // namespace gbl
