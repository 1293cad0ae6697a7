// Lit-image comparisons for the GL tests.
#include "lit_compare.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gbl::test {

std::string LitDiff::describe() const {
    char buf[160];
    std::snprintf(buf, sizeof buf, "max abs %.3g, mean abs %.3g (mean value %.3g), pixels over bound %d", maxAbs,
                  meanAbs, meanValue, pixelsOver);
    return buf;
}

LitDiff compareLit(FloatImage const& a, FloatImage const& ref, double relative, double absolute) {
    LitDiff d;
    EXPECT_EQ(a.width, ref.width);
    EXPECT_EQ(a.height, ref.height);
    if (a.width != ref.width || a.height != ref.height) return d;
    double sumErr = 0.0, sum = 0.0;
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) {
            bool over = false;
            for (int c = 0; c < 3; ++c) {
                double const va = a.at(x, y, c), vr = ref.at(x, y, c);
                double const e = std::abs(va - vr);
                d.maxAbs = std::max(d.maxAbs, e);
                sumErr += e;
                sum += std::abs(vr);
                if (e > relative * std::abs(vr) + absolute) over = true;
            }
            d.pixelsOver += over;
        }
    d.pixels = ref.width * ref.height;
    double const n = double(d.pixels) * 3;
    d.meanAbs = sumErr / n;
    d.meanValue = sum / n;
    return d;
}

void expectWithinBound(LitDiff const& d, std::string const& what, double minMean) {
    std::printf("%s: %s\n", what.c_str(), d.describe().c_str());
    EXPECT_GT(d.meanValue, minMean) << what << ": the frame should be visibly lit";
    EXPECT_LT(d.meanAbs, 0.01 * d.meanValue) << what << ": " << d.describe();
    EXPECT_LT(d.pixelsOver, d.pixels / 200) << what << ": " << d.describe();
}

Camera cameraInsideLight(Camera base, PointLight const& light) {
    base.position = light.position + glm::vec3(0.3f, 0.4f, 0.3f);
    base.lookAt(glm::vec3(light.position.x, 0.0f, light.position.z) + glm::vec3(0.0f, 0.0f, -2.0f));
    return base;
}

}  // namespace gbl::test
