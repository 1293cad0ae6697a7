// The bench command's results (one per mode, cull and light count) and how they are reported: the
// table printed to the terminal and the JSON file (app/bench_report.cpp).
#pragma once

#include "bench_command.h"
#include "cli_values.h"
#include "core/pipeline_settings.h"
#include "gl/caps.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gbl::bench {

struct Combination {
    LightingMode mode = LightingMode::Quad;
    CullMode cull = CullMode::Front;
    bool usesCull = false;  // the frames that draw light volumes (core/pipeline_settings.h, drawsLightVolumes)
    int lights = 0;
    float radiusScale = 1.0f;
    PrepassLights prepassLights = PrepassLights::Quad;  // prepass only: its light pass (--prepass-lights)
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

// Per-pair costs for every result, against quad at the same light count or the nearest one measured.
void fillPairCosts(std::vector<Result>& results);
void printTable(std::vector<Result> const& results, GlCaps const& caps, Size2 size, BenchOptions const& o);
nlohmann::json toJson(std::vector<Result> const& results, GlCaps const& caps, Size2 size, BenchOptions const& o);

}  // namespace gbl::bench
