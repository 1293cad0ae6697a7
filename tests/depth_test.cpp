// Depth linearisation (core/depth.h): exact ends, round trips through glm::perspective, and the
// float error near the far plane, where the textbook formula cancels.
#include "core/depth.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cfloat>
#include <cmath>

using namespace gbl;

namespace {

// The exact value for the given float input, in double: nf / (f - d (f - n)). With d, n and f
// exact doubles the subtraction loses nothing that matters at these magnitudes (53-bit mantissa).
double exactLinearDepth(float d, float n, float f) {
    return double(n) * double(f) / (double(f) - double(d) * (double(f) - double(n)));
}

// The textbook form written in float, as view.frag and image_range had it.
float textbookLinearDepth(float d, float n, float f) {
    float const ndc = d * 2.0f - 1.0f;
    return 2.0f * n * f / (f + n - ndc * (f - n));
}

double relativeError(float got, double exact) {
    return std::abs(double(got) - exact) / exact;
}

}  // namespace

TEST(Depth, EndsAreTheNearAndFarPlanes) {
    float const n = 0.1f, f = 200.0f;
    EXPECT_FLOAT_EQ(linearDepth(0.0f, n, f), n);
    EXPECT_FLOAT_EQ(linearDepth(1.0f, n, f), f);
    EXPECT_FLOAT_EQ(linearDepth(0.0f, 0.5f, 10.0f), 0.5f);
    EXPECT_FLOAT_EQ(linearDepth(1.0f, 0.5f, 10.0f), 10.0f);
}

TEST(Depth, RoundTripsThroughGlmPerspective) {
    float const n = 0.1f, f = 200.0f;
    glm::mat4 const proj = glm::perspective(glm::radians(60.0f), 16.0f / 9.0f, n, f);
    for (float d : {0.5f, 3.0f, 17.0f, 120.0f, 199.0f}) {
        glm::vec4 const clip = proj * glm::vec4(0.3f, -0.2f, -d, 1.0f);
        float const window = clip.z / clip.w * 0.5f + 0.5f;
        // The forward projection rounds window depth to float: 1e-3 relative covers that at
        // 199 units (f/n = 2000 amplifies one ulp of window depth to ~2.4e-4 relative).
        EXPECT_NEAR(linearDepth(window, n, f), d, d * 1e-3) << d;
    }
    // The same through the projection's own formula for NDC z.
    float const n2 = 0.1f, f2 = 100.0f, d = 10.0f;
    float const ndc = (f2 + n2) / (f2 - n2) - 2.0f * f2 * n2 / ((f2 - n2) * d);
    EXPECT_NEAR(linearDepth(ndc * 0.5f + 0.5f, n2, f2), d, 1e-3f);
}

TEST(Depth, StaysWithinAFewRoundingsNearTheFarPlane) {
    // n = 0.1, f = 1000: the textbook form loses log2(f / n) ~ 13 bits near d = 1.
    float const n = 0.1f, f = 1000.0f;
    // Bound: 1 - d is exact for d >= 0.5 (one rounding below), then two products, one sum, n*f
    // and the division each round once, all on positive numbers: at most ~5 half-ulps, so
    // 3 * FLT_EPSILON (6 half-ulps) holds for every d; a cancelling form is off by ~1e3 times more.
    double const bound = 3.0 * FLT_EPSILON;
    double worstStable = 0.0, worstTextbook = 0.0;
    auto probe = [&](float d) {
        double const exact = exactLinearDepth(d, n, f);
        worstStable = std::max(worstStable, relativeError(linearDepth(d, n, f), exact));
        worstTextbook = std::max(worstTextbook, relativeError(textbookLinearDepth(d, n, f), exact));
    };
    // The last 4096 floats below 1 (the far end of the depth range) and a sweep of the rest.
    float d = 1.0f;
    for (int i = 0; i < 4096; ++i) probe(d = std::nextafter(d, 0.0f));
    for (int i = 0; i <= 10000; ++i) probe(float(i) / 10000.0f);
    EXPECT_LE(worstStable, bound);
    // The reason for the rearrangement: the textbook form in float is far outside that bound.
    EXPECT_GT(worstTextbook, 100.0 * bound);
}
