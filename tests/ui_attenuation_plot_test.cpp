// The attenuation plot shows the renderer's numbers: the applied curve ends at the radius, the
// classic curve meets the threshold there.
#include "core/light_math.h"
#include "panels/attenuation_plot.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace gbl;
using namespace gbl::ui;

TEST(UiAttenuationPlot, CurvesMeetThresholdAndZeroAtTheRadius) {
    PointLight light;
    light.color = {1.0f, 0.5f, 0.25f};
    light.intensity = 2.0f;
    AttenuationCurve const c = sampleAttenuationCurve(light, 257);
    float const r = lightRadius(light).radius;
    EXPECT_FLOAT_EQ(c.radius, r);
    EXPECT_FLOAT_EQ(c.maxDistance, r * 1.25f);
    ASSERT_EQ(c.distance.size(), 257u);
    float const imax = lightImax(light);
    EXPECT_FLOAT_EQ(c.classic.front(), imax / light.kc);
    // The classic curve at the radius is the threshold: the definition of the radius.
    EXPECT_NEAR(imax * attenuation(light.kc, light.kl, light.kq, r), light.threshold, 1e-5f);
    for (std::size_t i = 0; i < c.distance.size(); ++i) {
        EXPECT_LE(c.applied[i], c.classic[i]);
        if (c.distance[i] >= r) {
            EXPECT_EQ(c.applied[i], 0.0f) << "d = " << c.distance[i];
        }
        if (i > 0) {
            EXPECT_LE(c.applied[i], c.applied[i - 1]);  // never brighter further away
        }
    }
    EXPECT_GT(c.applied[std::size_t(100)], 0.0f);  // 100/256 of 1.25 r is inside the radius
}

TEST(UiAttenuationPlot, LightBelowThresholdHasAnAxisButNoRadius) {
    PointLight light;
    light.intensity = 0.01f;  // Imax below threshold * Kc: never lights anything
    AttenuationCurve const c = sampleAttenuationCurve(light, 16);
    EXPECT_EQ(c.radius, 0.0f);
    EXPECT_GT(c.maxDistance, 0.0f);
    for (float v : c.applied) EXPECT_EQ(v, 0.0f);
}

// Issue 26: with the axis held, a smaller Kq (a larger radius) moves the curve instead of
// rescaling the axis under it: the value at a fixed distance grows.
TEST(UiAttenuationPlot, AFixedAxisShowsAChangeOfKq) {
    PointLight light;
    light.kq = 2.4f;
    float const axis = 2.0f * lightRadius(light).radius;
    AttenuationCurve const before = sampleAttenuationCurve(light, 33, axis);
    light.kq = 0.84f;
    AttenuationCurve const after = sampleAttenuationCurve(light, 33, axis);
    EXPECT_FLOAT_EQ(before.maxDistance, axis);
    EXPECT_FLOAT_EQ(after.maxDistance, axis);
    EXPECT_FLOAT_EQ(before.distance.back(), after.distance.back());
    EXPECT_GT(after.radius, before.radius);
    std::size_t const middle = 8;  // a quarter of the axis: inside both radii
    ASSERT_LT(before.distance[middle], before.radius);
    EXPECT_GT(after.applied[middle], before.applied[middle]);
}

TEST(UiAttenuationPlot, TheConePlotIsTheSpotsFactorFromOneToZero) {
    PointLight light;
    light.kind = LightKind::Spot;
    light.innerConeDeg = 20.0f;
    light.outerConeDeg = 40.0f;
    ConeCurve const c = sampleConeCurve(light, 101);
    ASSERT_EQ(c.degrees.size(), 101u);
    EXPECT_FLOAT_EQ(c.maxDegrees, 50.0f);  // a quarter past the outer angle
    for (std::size_t i = 0; i < c.degrees.size(); ++i) {
        float const a = c.degrees[i];
        EXPECT_EQ(c.factor[i], spotConeFactor(spotCone(light), std::cos(glm::radians(a))));
        if (a < 20.0f) {
            EXPECT_EQ(c.factor[i], 1.0f) << a;
        }
        if (a > 40.0f) {
            EXPECT_EQ(c.factor[i], 0.0f) << a;
        }
        if (i > 0) {
            EXPECT_LE(c.factor[i], c.factor[i - 1]);  // never brighter further off the axis
        }
    }
    EXPECT_GT(c.factor[60], 0.0f);  // 30 degrees: between inner and outer
    EXPECT_LT(c.factor[60], 1.0f);
}
