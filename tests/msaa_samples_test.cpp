// core/msaa_samples.h: how many distinct surfaces the samples of a pixel hold, on hand-made
// samples seen from the origin, with the thresholds of core/msaa.h.
#include "core/msaa_samples.h"

#include <gtest/gtest.h>

#include <array>

using namespace gbl;

namespace {

glm::vec3 const kEye{0.0f};

MsaaSampleValues floorAt(float x, glm::vec4 albedo = {0.5f, 0.5f, 0.5f, 0.2f}, float y = -1.0f) {
    return {{x, y, -10.0f, 1.0f}, {0.0f, 1.0f, 0.0f, 0.0f}, albedo};
}
MsaaSampleValues wallAt(float z) {
    return {{0.0f, 0.0f, z, 1.0f}, {0.0f, 0.0f, 1.0f, 0.0f}, {0.8f, 0.2f, 0.2f, 0.5f}};
}
MsaaSampleValues const kBackground{};

TEST(MsaaSamples, OneSurfaceIsOneWhateverTheSampleCount) {
    std::array<MsaaSampleValues, 8> s;
    s.fill(floorAt(0.0f));
    EXPECT_EQ(msaaDistinctSamples(s, kEye), 1);
    // Samples a little apart on the same floor: 0.05 units at 10 away is within 1 % of the distance.
    s[3] = floorAt(0.05f);
    EXPECT_EQ(msaaDistinctSamples(s, kEye), 1);
    std::array<MsaaSampleValues, 4> sky{kBackground, kBackground, kBackground, kBackground};
    EXPECT_EQ(msaaDistinctSamples(sky, kEye), 1);
    EXPECT_EQ(msaaDistinctSamples(std::span<MsaaSampleValues const>(), kEye), 0);
}

TEST(MsaaSamples, EachThresholdSeparatesSurfaces) {
    // Position: 0.2 units off the floor's plane at 10 away is 2 %, beyond 1 %; along the plane it
    // is the same floor (a layout that rebuilds each sample's position spreads them over the pixel).
    glm::vec4 const grey{0.5f, 0.5f, 0.5f, 0.2f};
    std::array<MsaaSampleValues, 2> far{floorAt(0.0f), floorAt(0.0f, grey, -1.2f)};
    EXPECT_EQ(msaaDistinctSamples(far, kEye), 2);
    std::array<MsaaSampleValues, 2> along{floorAt(0.0f), floorAt(0.5f)};
    EXPECT_EQ(msaaDistinctSamples(along, kEye), 1);
    std::array<MsaaSampleValues, 2> near{floorAt(0.0f), floorAt(0.0f, grey, -1.05f)};  // 0.5 %: the same
    EXPECT_EQ(msaaDistinctSamples(near, kEye), 1);
    // Normal: a floor and a wall at the same point.
    MsaaSampleValues tilted = floorAt(0.0f);
    tilted.normal = {0.0f, 0.9f, 0.436f, 0.0f};  // about 26 degrees from +Y, cosine 0.9 < 0.99
    std::array<MsaaSampleValues, 2> bent{floorAt(0.0f), tilted};
    EXPECT_EQ(msaaDistinctSamples(bent, kEye), 2);
    // Albedo: 0.1 apart in red, beyond 0.05; 0.04 apart is the same.
    std::array<MsaaSampleValues, 3> tint{floorAt(0.0f), floorAt(0.0f, {0.6f, 0.5f, 0.5f, 0.2f}),
                                         floorAt(0.0f, {0.54f, 0.5f, 0.5f, 0.2f})};
    EXPECT_EQ(msaaDistinctSamples(tint, kEye), 2);
    // Coverage: drawn against background.
    std::array<MsaaSampleValues, 4> edge{floorAt(0.0f), kBackground, floorAt(0.0f), kBackground};
    EXPECT_EQ(msaaDistinctSamples(edge, kEye), 2);
    EXPECT_FALSE(msaaSameSurface(floorAt(0.0f), kBackground, kEye));
}

TEST(MsaaSamples, CountsEverySurfaceUpToTheSampleCount) {
    std::array<MsaaSampleValues, 4> three{floorAt(0.0f), wallAt(-5.0f), kBackground, wallAt(-5.0f)};
    EXPECT_EQ(msaaDistinctSamples(three, kEye), 3);
    std::array<MsaaSampleValues, 8> eight;
    for (std::size_t i = 0; i < eight.size(); ++i)
        eight[i] = floorAt(0.0f, {0.1f * float(i), 0.5f, 0.5f, 0.2f});  // albedo 0.1 apart each
    EXPECT_EQ(msaaDistinctSamples(eight, kEye), 8);
}

}  // namespace
