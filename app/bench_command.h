// `gbuffer-lab bench`: GPU time per pass and per frame for each lighting mode and light count.
#pragma once

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace gbl {

struct BenchOptions {
    std::string size = "1280x720";
    std::vector<int> lights{32, 256, 1024, 4096};
    std::vector<std::string> modes{"quad", "volumes", "tiled", "forward"};
    // Cull modes measured for `volumes` (each one is its own combination); other modes ignore it.
    std::vector<std::string> culls{"front"};
    int frames = 20;            // measured frames per combination
    int warmup = 3;             // frames rendered and thrown away first (shader and cache warm-up)
    double budgetSeconds = 60;  // wall-clock budget per combination, warm-up included
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

}  // namespace gbl
