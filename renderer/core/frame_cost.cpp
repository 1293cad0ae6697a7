// Estimating a frame's lighting cost before it runs.
#include "core/frame_cost.h"

#include "core/light_math.h"
#include "core/tile_math.h"

#include <algorithm>
#include <cstdio>

namespace gbl {

namespace {
std::string modeName(LightingMode m) {
    return std::string(kLightingModeNames[std::size_t(m)]);
}

std::string seconds(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, s < 10.0 ? "%.1f s" : "%.0f s", s);
    return buf;
}
}  // namespace

double evaluatedPairs(LightingMode mode, std::span<PointLight const> lights, Camera const& camera, int width,
                      int height) {
    if (width <= 0 || height <= 0) return 0.0;
    double const pixels = double(width) * double(height);
    if (mode == LightingMode::Quad || mode == LightingMode::Forward || mode == LightingMode::Prepass)
        return pixels * double(lights.size());
    TileGrid const grid = tileGrid(width, height);
    glm::mat4 const view = camera.view();
    glm::mat4 const projection = camera.projection(float(width) / float(height));
    double pairs = 0.0;
    for (PointLight const& l : lights) {
        if (!isLocalLight(l)) {
            pairs += pixels;
            continue;
        }
        float const r = lightRadius(l).radius;
        glm::vec3 const centre = glm::vec3(view * glm::vec4(l.position, 1.0f));
        TileRange const t =
            sphereTileRange(projection, width, height, grid, centre, r, camera.nearPlane, camera.farPlane);
        if (t.empty()) continue;
        double const tiles = double(t.x1 - t.x0 + 1) * double(t.y1 - t.y0 + 1);
        pairs += std::min(tiles * double(grid.tileSize * grid.tileSize), pixels);
    }
    return pairs;
}

FrameCostEstimate estimateFrameCost(LightingMode mode, std::span<PointLight const> lights, Camera const& camera,
                                    int width, int height, double secondsPerPair) {
    double const pairs = evaluatedPairs(mode, lights, camera, width, height);
    return {mode, pairs, pairs * secondsPerPair};
}

std::optional<FrameCostEstimate> cheaperMode(FrameCostEstimate const& current, std::span<LightingMode const> available,
                                             std::span<PointLight const> lights, Camera const& camera, int width,
                                             int height, double secondsPerPair) {
    std::optional<FrameCostEstimate> best;
    for (LightingMode m : available) {
        if (m == current.mode) continue;
        FrameCostEstimate const e = estimateFrameCost(m, lights, camera, width, height, secondsPerPair);
        if (e.seconds < current.seconds && (!best || e.seconds < best->seconds)) best = e;
    }
    return best;
}

std::string describeFrameCost(FrameCostEstimate const& estimate, int lights, int width, int height,
                              double secondsPerPair, std::optional<FrameCostEstimate> const& cheaper) {
    char pairs[64];
    std::snprintf(pairs, sizeof pairs, "%.2g light-pixel pairs at %.2g ns each", estimate.pairs, secondsPerPair * 1e9);
    std::string s = "this frame is estimated at " + seconds(estimate.seconds) + " in " + modeName(estimate.mode) +
                    " mode (" + std::to_string(lights) + " lights, " + std::to_string(width) + "x" +
                    std::to_string(height) + ": " + pairs + ")";
    if (cheaper)
        s += "; " + modeName(cheaper->mode) + " mode gives the same image in about " + seconds(cheaper->seconds);
    return s;
}

}  // namespace gbl
