// The count heat maps' one colour scale (core/heat_scale.h): bin edges, labels and colours.
#include "core/heat_scale.h"

#include <gtest/gtest.h>

#include <limits>

using namespace gbl;

TEST(HeatScale, BinEdgesAreExact) {
    EXPECT_EQ(heatBin(0.0f), 0);
    EXPECT_EQ(heatBin(1.0f), 1);
    EXPECT_EQ(heatBin(2.0f), 2);
    EXPECT_EQ(heatBin(3.0f), 2);
    EXPECT_EQ(heatBin(4.0f), 3);
    EXPECT_EQ(heatBin(7.0f), 3);
    EXPECT_EQ(heatBin(8.0f), 4);
    EXPECT_EQ(heatBin(15.0f), 4);
    EXPECT_EQ(heatBin(16.0f), 5);
    EXPECT_EQ(heatBin(31.0f), 5);
    EXPECT_EQ(heatBin(32.0f), 6);
    EXPECT_EQ(heatBin(63.0f), 6);
    EXPECT_EQ(heatBin(64.0f), 7);
    EXPECT_EQ(heatBin(1e6f), 7);
    EXPECT_EQ(heatBin(std::numeric_limits<float>::infinity()), 7);
}

TEST(HeatScale, NanAndNegativeCountsFallInBinZero) {
    EXPECT_EQ(heatBin(std::numeric_limits<float>::quiet_NaN()), 0);
    EXPECT_EQ(heatBin(-1.0f), 0);
    EXPECT_EQ(heatBin(-std::numeric_limits<float>::infinity()), 0);
    EXPECT_EQ(heatBin(0.5f), 0);  // counts are whole; a fraction below 1 is no light
}

TEST(HeatScale, EveryBinHoldsTheCountsFromItsEdgeToTheNext) {
    for (int k = 0; k < kHeatBins; ++k) {
        int const lo = kHeatBinEdges[std::size_t(k)];
        int const hi = k + 1 < kHeatBins ? kHeatBinEdges[std::size_t(k) + 1] - 1 : 1000;
        for (int c = lo; c <= hi; ++c) EXPECT_EQ(heatBin(float(c)), k) << "count " << c;
    }
}

TEST(HeatScale, LabelsAndRanges) {
    char const* const labels[] = {"0", "1", "2", "4", "8", "16", "32", "64+"};
    char const* const ranges[] = {"0", "1", "2-3", "4-7", "8-15", "16-31", "32-63", "64+"};
    for (int k = 0; k < kHeatBins; ++k) {
        EXPECT_EQ(heatBinLabel(k), labels[k]);
        EXPECT_EQ(heatBinRange(k), ranges[k]);
    }
    EXPECT_EQ(heatBinLabel(8), "?");
    EXPECT_EQ(heatBinRange(-1), "?");
}

TEST(HeatScale, BinColoursAreDistinctAndZeroIsBlack) {
    EXPECT_EQ(heatBinColor(0), glm::vec3(0.0f));
    // A count is read off the colour: every pair of bins differs by far more than 8-bit rounding,
    // and so do their dimmed (wasted-work) versions.
    for (int a = 0; a < kHeatBins; ++a)
        for (int b = a + 1; b < kHeatBins; ++b) {
            EXPECT_GT(glm::length(heatBinColor(a) - heatBinColor(b)), 0.2f) << a << " vs " << b;
            EXPECT_GT(glm::length(kHeatWastedDim * (heatBinColor(a) - heatBinColor(b))), 0.05f) << a << " vs " << b;
        }
    EXPECT_EQ(heatBinColor(-3), heatBinColor(0));
    EXPECT_EQ(heatBinColor(99), heatBinColor(kHeatBins - 1));
}

TEST(HeatScale, HeatMapDimsByTheShareThatLit) {
    glm::vec3 const c = heatBinColor(3);
    EXPECT_EQ(heatMapColor(5.0f, 5.0f), c);                   // all lit: full colour
    EXPECT_EQ(heatMapColor(5.0f, 0.0f), c * kHeatWastedDim);  // none lit
    glm::vec3 const half = heatMapColor(4.0f, 2.0f);
    EXPECT_NEAR(half.g, c.g * (kHeatWastedDim + 0.5f * (1.0f - kHeatWastedDim)), 1e-6f);
    EXPECT_EQ(heatMapColor(0.0f, 0.0f), glm::vec3(0.0f));
    EXPECT_EQ(heatMapColor(2.0f, 9.0f), heatBinColor(2));  // lit above evaluated is clamped
}

TEST(HeatScale, QuantityNamesFollowViewAndMode) {
    EXPECT_EQ(heatQuantity(DebugView::TileLights, LightingMode::Clustered), "lights per tile");
    EXPECT_EQ(heatQuantity(DebugView::Heatmap, LightingMode::Volumes), "volumes per pixel");
    EXPECT_EQ(heatQuantity(DebugView::Heatmap, LightingMode::Tiled), "lights per tile");
    EXPECT_EQ(heatQuantity(DebugView::Heatmap, LightingMode::Clustered), "lights per cluster");
}
