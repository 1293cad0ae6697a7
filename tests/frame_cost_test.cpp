// The long-frame estimate (core/frame_cost.h): pairs per mode, the cheaper mode, the sentence.
#include "core/frame_cost.h"
#include "core/light_math.h"

#include <gtest/gtest.h>

#include <vector>

namespace gbl {
namespace {

Camera lookingDown() {
    Camera c;
    c.position = {0.0f, 20.0f, 0.01f};
    c.lookAt({0.0f, 0.0f, 0.0f});
    return c;
}

std::vector<PointLight> smallLights(int n) {
    std::vector<PointLight> lights;
    for (int i = 0; i < n; ++i) {
        PointLight l;
        l.position = {float(i % 10) - 5.0f, 0.5f, float(i / 10 % 10) - 5.0f};
        l.intensity = 0.1f;
        l.kl = 0.7f;
        l.kq = 1.8f;  // radius about 1.5: a few tiles each seen from 20 units up
        lights.push_back(l);
    }
    return lights;
}

TEST(FrameCost, FullScreenModesEvaluateEveryLightAtEveryPixel) {
    auto const lights = smallLights(100);
    EXPECT_DOUBLE_EQ(evaluatedPairs(LightingMode::Quad, lights, lookingDown(), 1280, 720), 1280.0 * 720.0 * 100.0);
    EXPECT_DOUBLE_EQ(evaluatedPairs(LightingMode::Forward, lights, lookingDown(), 1280, 720), 1280.0 * 720.0 * 100.0);
    EXPECT_DOUBLE_EQ(evaluatedPairs(LightingMode::Quad, lights, lookingDown(), 0, 720), 0.0);
}

TEST(FrameCost, CulledModesEvaluateOnlyTheLightsTiles) {
    auto const lights = smallLights(100);
    double const quad = evaluatedPairs(LightingMode::Quad, lights, lookingDown(), 1280, 720);
    double const tiled = evaluatedPairs(LightingMode::Tiled, lights, lookingDown(), 1280, 720);
    EXPECT_GT(tiled, 0.0);
    EXPECT_LT(tiled, quad / 10.0);  // small lights seen from far above cover a few tiles each
    EXPECT_DOUBLE_EQ(tiled, evaluatedPairs(LightingMode::Clustered, lights, lookingDown(), 1280, 720));
    // A light behind the camera costs nothing; a directional light costs every pixel.
    PointLight behind;
    behind.position = {0.0f, 40.0f, 0.0f};
    EXPECT_DOUBLE_EQ(evaluatedPairs(LightingMode::Tiled, std::vector<PointLight>{behind}, lookingDown(), 64, 64), 0.0);
    PointLight sun;
    sun.kind = LightKind::Directional;
    EXPECT_DOUBLE_EQ(evaluatedPairs(LightingMode::Tiled, std::vector<PointLight>{sun}, lookingDown(), 64, 64), 4096.0);
}

TEST(FrameCost, TheCheaperModeIsTheCheapestAvailableOne) {
    auto const lights = smallLights(100);
    FrameCostEstimate const quad =
        estimateFrameCost(LightingMode::Quad, lights, lookingDown(), 1280, 720, kSoftwareSecondsPerPair);
    EXPECT_NEAR(quad.seconds, 1280.0 * 720.0 * 100.0 * 3.5e-9, 1e-9);
    std::vector<LightingMode> const available{LightingMode::Quad, LightingMode::Volumes, LightingMode::Tiled};
    auto const cheaper = cheaperMode(quad, available, lights, lookingDown(), 1280, 720, kSoftwareSecondsPerPair);
    ASSERT_TRUE(cheaper.has_value());
    EXPECT_NE(cheaper->mode, LightingMode::Quad);
    EXPECT_LT(cheaper->seconds, quad.seconds);
    // Nothing cheaper when only the full-screen pass is available.
    std::vector<LightingMode> const onlyQuad{LightingMode::Quad};
    EXPECT_FALSE(cheaperMode(quad, onlyQuad, lights, lookingDown(), 1280, 720, kSoftwareSecondsPerPair));
}

TEST(FrameCost, TheSentenceGivesTheEstimateAndTheFasterMode) {
    FrameCostEstimate const quad{LightingMode::Quad, 9.2e10, 322.0};
    FrameCostEstimate const tiled{LightingMode::Tiled, 6.0e8, 2.1};
    std::string const s = describeFrameCost(quad, 100000, 1280, 720, 3.5e-9, tiled);
    EXPECT_EQ(s,
              "this frame is estimated at 322 s in quad mode (100000 lights, 1280x720: 9.2e+10 light-pixel pairs at "
              "3.5 ns each); tiled mode gives the same image in about 2.1 s");
}

}  // namespace
}  // namespace gbl
