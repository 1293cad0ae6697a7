// The angle between decoded normals (issue 12): known normals at known angles, and the per-pixel
// statistics the A/B "normal angle" heat map shows.
#include "model/normal_angle.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace gbl;
using namespace gbl::ui;

namespace {

// A normal turned from +z towards +y by `degrees`.
glm::vec3 tilted(float degrees) {
    float const r = glm::radians(degrees);
    return {0.0f, std::sin(r), std::cos(r)};
}

// A 4-channel image of the given (normal, drawn) pixels in one row.
FloatImage row(std::initializer_list<std::pair<glm::vec3, bool>> px) {
    FloatImage img{int(px.size()), 1, 4, {}};
    for (auto const& [n, drawn] : px) img.pixels.insert(img.pixels.end(), {n.x, n.y, n.z, drawn ? 1.0f : 0.0f});
    return img;
}

}  // namespace

TEST(NormalAngle, KnownAngles) {
    EXPECT_NEAR(angleDegrees({0, 0, 1}, {1, 0, 0}), 90.0f, 1e-5f);
    EXPECT_NEAR(angleDegrees({0, 0, 1}, {0, 0, -1}), 180.0f, 1e-5f);
    EXPECT_EQ(angleDegrees({0, 0, 1}, {0, 0, 1}), 0.0f);
    EXPECT_NEAR(angleDegrees({1, 1, 0}, {1, 0, 0}), 45.0f, 1e-5f);
    // Lengths do not matter (decoded normals need not be unit).
    EXPECT_NEAR(angleDegrees({0, 0, 3}, {0, 0.5f, 0}), 90.0f, 1e-5f);
    // Small angles, where acos(dot) would lose them: 1 degree and 0.01 degree to 1e-4 relative.
    EXPECT_NEAR(angleDegrees({0, 0, 1}, tilted(1.0f)), 1.0f, 1e-4f);
    EXPECT_NEAR(angleDegrees({0, 0, 1}, tilted(0.01f)), 0.01f, 1e-6f);
    EXPECT_TRUE(std::isnan(angleDegrees({0, 0, 0}, {0, 0, 1})));
    EXPECT_TRUE(std::isnan(angleDegrees({NAN, 0, 1}, {0, 0, 1})));
}

TEST(NormalAngle, PerPixelStatistics) {
    // Pixels: background on both sides, equal, 2 degrees apart, 90 degrees apart, drawn in A only.
    FloatImage const a =
        row({{{0, 0, 0}, false}, {{0, 0, 1}, true}, {tilted(2.0f), true}, {{1, 0, 0}, true}, {{0, 0, 1}, true}});
    FloatImage const b =
        row({{{0, 0, 0}, false}, {{0, 0, 1}, true}, {{0, 0, 1}, true}, {{0, 0, 1}, true}, {{0, 0, 0}, false}});
    DiffStats const d = normalAngleDiff(a, b, 1.0f);
    ASSERT_TRUE(d.comparable);
    EXPECT_EQ(d.pixels, 4);     // the background on both sides is not compared
    EXPECT_EQ(d.nanPixels, 1);  // geometry on one side only
    EXPECT_NEAR(d.max, 90.0f, 1e-5f);
    EXPECT_EQ(d.maxAt, glm::ivec2(3, 0));
    EXPECT_NEAR(d.mean, (0.0 + 2.0 + 90.0) / 3.0, 1e-4);
    EXPECT_EQ(d.overThreshold, 2);  // 2 and 90 degrees are over 1 degree
    EXPECT_EQ(d.diff.at(0, 0, 0), 0.0f);
    EXPECT_NEAR(d.diff.at(2, 0, 0), 2.0f, 1e-4f);
    EXPECT_TRUE(std::isnan(d.diff.at(4, 0, 0)));
}

TEST(NormalAngle, DifferentSizesAreNotComparable) {
    FloatImage const a = row({{{0, 0, 1}, true}});
    FloatImage const b = row({{{0, 0, 1}, true}, {{0, 0, 1}, true}});
    EXPECT_FALSE(normalAngleDiff(a, b, 1.0f).comparable);
    FloatImage three{1, 1, 3, {0, 0, 1}};  // no drawn flag
    EXPECT_FALSE(normalAngleDiff(three, three, 1.0f).comparable);
}
