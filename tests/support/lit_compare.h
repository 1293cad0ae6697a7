// Comparing two lit images (or light targets) within the bound the tests of the lighting modes share,
// and the camera inside a light's volume they look from.
#pragma once

#include "core/camera.h"
#include "core/frame_types.h"
#include "core/point_light.h"

#include <string>

namespace gbl::test {

struct LitDiff {
    double maxAbs = 0.0;
    double meanAbs = 0.0;
    double meanValue = 0.0;  // of the reference
    int pixelsOver = 0;      // pixels with a channel over the bound
    int pixels = 0;          // pixels compared
    std::string describe() const;
};

// Channels 0..2 of `a` against `ref`, each pixel over the bound when a channel differs by more than
// `relative` of the reference's value + `absolute`. The defaults are forward's bound against quad
// (light_modes_gl_test, prepass_gl_test): 3 % + 2e-3.
LitDiff compareLit(FloatImage const& a, FloatImage const& ref, double relative = 0.03, double absolute = 2e-3);

// The shared verdict on a LitDiff: the frame is visibly lit (mean value over `minMean`), the mean error
// is under 1 % of the mean value, and under 0.5 % of the pixels are over the bound.
void expectWithinBound(LitDiff const& d, std::string const& what, double minMean = 0.01);

// `base` moved inside `light`'s sphere (0.3, 0.4, 0.3 from it), looking at the floor 2 units beyond
// the point under it, as light_modes_gl_test's camera inside a volume.
Camera cameraInsideLight(Camera base, PointLight const& light);

}  // namespace gbl::test
