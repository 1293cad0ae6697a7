// The long-frame warning.
#include "long_frame.h"

#include <vector>

namespace gbl {

double assumedSecondsPerPair(GlCaps const& caps) {
    return caps.masksBranches ? kSoftwareSecondsPerPair : kHardwareSecondsPerPair;
}

std::optional<LongFrameWarning> longFrameWarning(Renderer& renderer, FrameInput const& input, double thresholdSeconds) {
    int const w = renderer.width(), h = renderer.height();
    std::span<PointLight const> const lights = shadedLights(input);
    double const perPair = assumedSecondsPerPair(renderer.caps());
    FrameCostEstimate const e = estimateFrameCost(input.settings.mode, lights, input.camera, w, h, perPair);
    if (!(e.seconds > thresholdSeconds)) return std::nullopt;
    std::vector<LightingMode> available;
    // Ties go to the first: tiled is the fastest mode per evaluated pair in bench on llvmpipe.
    for (LightingMode m : {LightingMode::Tiled, LightingMode::Clustered, LightingMode::Volumes, LightingMode::Quad})
        if (!renderer.modeUnavailable(m)) available.push_back(m);
    LongFrameWarning warning;
    warning.estimate = e;
    warning.cheaper = cheaperMode(e, available, lights, input.camera, w, h, perPair);
    warning.message = describeFrameCost(e, int(lights.size()), w, h, perPair, warning.cheaper);
    return warning;
}

}  // namespace gbl
