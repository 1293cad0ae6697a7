// Viewer range fitting: background skipped, channel masks honoured, depth linearised.
#include "model/image_range.h"

#include "core/depth.h"

#include <gtest/gtest.h>

using namespace gbl;
using namespace gbl::ui;

namespace {
FloatImage image(int w, int h, int channels, std::vector<float> pixels) {
    return FloatImage{w, h, channels, std::move(pixels)};
}
}  // namespace

TEST(UiImageRange, SkipsBackgroundAndHonoursTheMask) {
    // Two drawn pixels (w = 1) and one background pixel (w = 0) holding huge values.
    FloatImage const img = image(3, 1, 4, {-5, 2, 7, 1, 100, 100, 100, 0, 3, -1, 9, 1});
    ValueRange const all = fitRange(img, 0x7, RangeSkip::ZeroAlpha);
    EXPECT_EQ(all.samples, 6);
    EXPECT_FLOAT_EQ(all.min, -5.0f);
    EXPECT_FLOAT_EQ(all.max, 9.0f);
    ValueRange const green = fitRange(img, 0x2, RangeSkip::ZeroAlpha);
    EXPECT_FLOAT_EQ(green.min, -1.0f);
    EXPECT_FLOAT_EQ(green.max, 2.0f);
    ValueRange const withBackground = fitRange(img, 0x7, RangeSkip::None);
    EXPECT_FLOAT_EQ(withBackground.max, 100.0f);
}

TEST(UiImageRange, DepthSkipsTheClearValueAndLinearises) {
    // linearDepth itself is tested in depth_test.cpp; here only that the fit uses it.
    float const n = 0.1f, f = 100.0f;
    // Window depth of a point 10 units away under the same projection, computed forward.
    float const d = 10.0f;
    float const ndc = (f + n) / (f - n) - 2.0f * f * n / ((f - n) * d);
    float const window = ndc * 0.5f + 0.5f;

    FloatImage const depth = image(3, 1, 1, {window, 1.0f, 0.5f});
    ValueRange const raw = fitRange(depth, 0x1, RangeSkip::FarDepth);
    EXPECT_EQ(raw.samples, 2);
    EXPECT_FLOAT_EQ(raw.max, window);
    ValueRange const lin = fitRange(depth, 0x1, RangeSkip::FarDepth, true, n, f);
    EXPECT_NEAR(lin.max, d, 1e-3f);
    EXPECT_NEAR(lin.min, linearDepth(0.5f, n, f), 1e-5f);
}

TEST(UiImageRange, EmptyAndFlatImages) {
    EXPECT_EQ(fitRange(image(2, 1, 1, {1.0f, 1.0f}), 0x1, RangeSkip::FarDepth).samples, 0);
    ValueRange const flat = fitRange(image(2, 1, 1, {0.25f, 0.25f}), 0x1, RangeSkip::None);
    EXPECT_GT(flat.max, flat.min);  // never an empty range, the remap divides by it
}
