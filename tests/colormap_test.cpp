// Colormaps: end points, monotone lightness where the map promises it, and legend ticks in data units.
#include "model/colormap.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace gbl;
using namespace gbl::ui;

namespace {
float luma(glm::vec3 c) {
    return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}
}  // namespace

TEST(Colormap, GreyIsTheValueClamped) {
    EXPECT_EQ(colormap(Colormap::Grey, 0.25f), glm::vec3(0.25f));
    EXPECT_EQ(colormap(Colormap::Grey, -1.0f), glm::vec3(0.0f));
    EXPECT_EQ(colormap(Colormap::Grey, 7.0f), glm::vec3(1.0f));
    EXPECT_EQ(colormap(Colormap::Grey, std::nanf("")), glm::vec3(0.0f));
}

TEST(Colormap, ViridisRunsFromDarkPurpleToYellowAndGetsLighter) {
    glm::vec3 const lo = colormap(Colormap::Viridis, 0.0f), hi = colormap(Colormap::Viridis, 1.0f);
    EXPECT_GT(lo.b, lo.g);  // purple: blue and red over green
    EXPECT_GT(lo.r, lo.g);
    EXPECT_GT(hi.r, 0.9f);  // yellow
    EXPECT_GT(hi.g, 0.85f);
    EXPECT_LT(hi.b, 0.2f);
    // Viridis is designed to be perceptually ordered: luma rises at every step of 1/64.
    for (int i = 1; i <= 64; ++i)
        EXPECT_GT(luma(colormap(Colormap::Viridis, float(i) / 64.0f)),
                  luma(colormap(Colormap::Viridis, float(i - 1) / 64.0f)))
            << i;
}

TEST(Colormap, TurboGoesBlueGreenRed) {
    glm::vec3 const q = colormap(Colormap::Turbo, 0.15f), m = colormap(Colormap::Turbo, 0.5f),
                    r = colormap(Colormap::Turbo, 0.9f);
    EXPECT_GT(q.b, q.r);
    EXPECT_GT(m.g, m.r);
    EXPECT_GT(m.g, m.b);
    EXPECT_GT(r.r, r.g);
    EXPECT_GT(r.r, r.b);
    // Stops are interpolated linearly: half way between stop 0 and stop 1 is their average.
    glm::vec3 const s0 = colormap(Colormap::Turbo, 0.0f), s1 = colormap(Colormap::Turbo, 1.0f / 32.0f);
    glm::vec3 const half = colormap(Colormap::Turbo, 0.5f / 32.0f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(half[c], 0.5f * (s0[c] + s1[c]), 1e-6f);
}

TEST(Colormap, LegendTicksAreRoundValuesInDataUnits) {
    auto t = legendTicks(0.0f, 1.0f, 5);
    ASSERT_EQ(t.size(), 6u);  // step 0.2: 0, 0.2, ..., 1
    EXPECT_FLOAT_EQ(t[1].value, 0.2f);
    EXPECT_FLOAT_EQ(t[1].position, 0.2f);
    EXPECT_FLOAT_EQ(t[5].value, 1.0f);
    // -3.7 .. 12.2 in about 4: step 5 -> 0, 5, 10 at positions (v + 3.7) / 15.9.
    t = legendTicks(-3.7f, 12.2f, 4);
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[0].value, 0.0f);
    EXPECT_FLOAT_EQ(t[2].value, 10.0f);
    EXPECT_NEAR(t[2].position, 13.7f / 15.9f, 1e-6f);
    // Depth in eye units 0.1 .. 100 -> step 20 (20 * 10^1 >= 99.9 / 5).
    t = legendTicks(0.1f, 100.0f, 5);
    ASSERT_FALSE(t.empty());
    EXPECT_EQ(t[0].value, 20.0f);
    EXPECT_TRUE(legendTicks(1.0f, 1.0f).empty());
    EXPECT_TRUE(legendTicks(0.0f, INFINITY).empty());
}
