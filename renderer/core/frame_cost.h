// What a frame's lighting will cost, estimated before it runs, so a frame that would take minutes
// says so first (render prints it; the editor switches to a mode that gives the same image).
// Light·pixel pairs are the unit: the full-screen pass evaluates every light at every pixel; the
// modes that cull evaluate a light only at the pixels of its sphere's screen rectangle.
#pragma once

#include "core/camera.h"
#include "core/pipeline_settings.h"
#include "core/point_light.h"

#include <optional>
#include <span>
#include <string>

namespace gbl {

// Seconds per light·pixel pair until a frame has been measured: the software rasteriser's from
// bench (llvmpipe on 2 cores, 512 lights at 1280x720: quad 1584-1688 ms for 472M pairs, about
// 3.5 ns), and a GPU's taken as a hundred times less, which only matters for frames with hundreds
// of millions of pairs.
inline constexpr double kSoftwareSecondsPerPair = 3.5e-9;
inline constexpr double kHardwareSecondsPerPair = 3.5e-11;

// Light·pixel pairs `mode` evaluates for these lights seen by `camera` at width x height.
//   quad, forward: every pixel with every light.
//   volumes, tiled, clustered: every pixel with each directional light, and each point or spot
//   light at the pixels of the tiles its bounding sphere covers (core/tile_math.h's
//   sphereTileRange, the binning pass's own rectangle).
double evaluatedPairs(LightingMode mode, std::span<PointLight const> lights, Camera const& camera, int width,
                      int height);

struct FrameCostEstimate {
    LightingMode mode = LightingMode::Quad;
    double pairs = 0.0;
    double seconds = 0.0;
};

// The frame's estimate in `mode` at `secondsPerPair`.
FrameCostEstimate estimateFrameCost(LightingMode mode, std::span<PointLight const> lights, Camera const& camera,
                                    int width, int height, double secondsPerPair);

// The cheapest of `available` (modes that give the same image: every mode but the debug views'),
// when it is cheaper than `current`.
std::optional<FrameCostEstimate> cheaperMode(FrameCostEstimate const& current, std::span<LightingMode const> available,
                                             std::span<PointLight const> lights, Camera const& camera, int width,
                                             int height, double secondsPerPair);

// "this frame is estimated at 313 s in quad mode (100000 lights x 921600 pixels = 9.2e10 light-pixel
// pairs at 3.5 ns each)" and, with a cheaper mode, "; tiled mode gives the same image in about 2.1 s".
std::string describeFrameCost(FrameCostEstimate const& estimate, int lights, int width, int height,
                              double secondsPerPair, std::optional<FrameCostEstimate> const& cheaper);

}  // namespace gbl
