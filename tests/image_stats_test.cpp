// Viewer statistics on images whose content is known exactly: histogram counts, percentile fits,
// NaN/Inf/negative counts, clipping counts, region statistics and the difference of two images.
#include "model/image_stats.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace gbl;
using namespace gbl::ui;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// 10x10, one channel, value of texel (x, y) = y * 10 + x + 1: the numbers 1..100 row by row.
FloatImage ramp100() {
    FloatImage img{10, 10, 1, {}};
    for (int i = 0; i < 100; ++i) img.pixels.push_back(float(i + 1));
    return img;
}

}  // namespace

TEST(ImageStats, MinMaxMeanOfOneToHundred) {
    ImageStats const s = imageStats(ramp100(), 0x1);
    EXPECT_EQ(s.pixels, 100);
    EXPECT_EQ(s.shown.finite, 100);
    EXPECT_EQ(s.shown.min, 1.0f);
    EXPECT_EQ(s.shown.max, 100.0f);
    EXPECT_DOUBLE_EQ(s.shown.mean, 50.5);
    EXPECT_EQ(s.shown.nan, 0);
    EXPECT_EQ(s.shown.negative, 0);
}

TEST(ImageStats, CountsNaNInfAndNegativePerChannelAndPerPixel) {
    // 4 pixels, 2 channels: (NaN, 1) (Inf, -2) (-Inf, NaN) (3, 4).
    FloatImage img{2, 2, 2, {kNaN, 1.0f, kInf, -2.0f, -kInf, kNaN, 3.0f, 4.0f}};
    ImageStats const s = imageStats(img, 0x3);
    EXPECT_EQ(s.channel[0].nan, 1);
    EXPECT_EQ(s.channel[0].inf, 2);
    EXPECT_EQ(s.channel[0].negative, 1);  // -Inf
    EXPECT_EQ(s.channel[0].finite, 1);
    EXPECT_EQ(s.channel[0].min, 3.0f);
    EXPECT_EQ(s.channel[1].nan, 1);
    EXPECT_EQ(s.channel[1].negative, 1);  // -2
    EXPECT_EQ(s.channel[1].min, -2.0f);
    EXPECT_EQ(s.channel[1].max, 4.0f);
    EXPECT_DOUBLE_EQ(s.channel[1].mean, 1.0);  // (1 - 2 + 4) / 3
    EXPECT_EQ(s.nanPixels, 2);
    EXPECT_EQ(s.infPixels, 2);
    EXPECT_EQ(s.negativePixels, 2);
    // Channel 1 alone: one NaN pixel, no Inf.
    ImageStats const g = imageStats(img, 0x2);
    EXPECT_EQ(g.nanPixels, 1);
    EXPECT_EQ(g.infPixels, 0);
}

TEST(ImageStats, HistogramCountsEveryValueInItsBin) {
    // 1..100 over [0, 100) in 10 bins: bin 0 holds 1..9 (9 values), bins 1..8 hold 10 each,
    // bin 9 holds 90..100 (11: the top edge falls in the last bin).
    Histogram const h = histogram(ramp100(), 0x1, 0.0f, 100.0f, 10);
    ASSERT_EQ(h.bins.size(), 10u);
    EXPECT_EQ(h.bins[0], 9);
    for (int i = 1; i < 9; ++i) EXPECT_EQ(h.bins[std::size_t(i)], 10) << i;
    EXPECT_EQ(h.bins[9], 11);
    EXPECT_EQ(h.below, 0);
    EXPECT_EQ(h.above, 0);
    EXPECT_EQ(h.maxBin(), 11);
    // A narrower range: values outside are counted, not binned; NaN and Inf are neither.
    FloatImage img = ramp100();
    img.pixels[0] = kNaN;
    img.pixels[1] = kInf;
    Histogram const n = histogram(img, 0x1, 20.5f, 80.5f, 4);
    EXPECT_EQ(n.below, 18);  // 3..20
    EXPECT_EQ(n.above, 20);  // 81..100
    EXPECT_EQ(n.bins[0] + n.bins[1] + n.bins[2] + n.bins[3], 60);
    EXPECT_EQ(n.bins[0], 15);  // 21..35
}

TEST(ImageStats, PercentileFitIgnoresNaNAndInf) {
    // 1..100: nearest-rank 1st percentile is 1, 99th is 99.
    ValueRange const r = percentileRange(ramp100(), 0x1, 1.0f, 99.0f);
    EXPECT_EQ(r.min, 1.0f);
    EXPECT_EQ(r.max, 99.0f);
    EXPECT_EQ(r.samples, 100);
    // NaN and Inf take no rank: with 71 and 81 replaced by them, 98 finite values remain;
    // rank ceil(0.98) = 1 is 1 and rank ceil(97.02) = 98 is 100.
    FloatImage img = ramp100();
    img.pixels[70] = kNaN;
    img.pixels[80] = kInf;
    ValueRange const p = percentileRange(img, 0x1, 1.0f, 99.0f);
    EXPECT_EQ(p.samples, 98);
    EXPECT_EQ(p.min, 1.0f);
    EXPECT_EQ(p.max, 100.0f);
    // The 50th percentile is rank 49: the values below 71 are 1..70, so rank 49 is 49.
    EXPECT_EQ(percentileRange(img, 0x1, 50.0f, 50.0f).min, 49.0f);
}

TEST(ImageStats, PercentileFitOfTwoHundredValuesDropsOneAtEachEnd) {
    // 200 values: -1e9, then 1..198, then +1e9. 1st percentile = rank 2 = 1, 99th = rank 198 = 197.
    FloatImage img{200, 1, 1, {}};
    img.pixels.push_back(-1e9f);
    for (int i = 1; i <= 198; ++i) img.pixels.push_back(float(i));
    img.pixels.push_back(1e9f);
    ValueRange const r = percentileRange(img, 0x1, 1.0f, 99.0f);
    EXPECT_EQ(r.min, 1.0f);
    EXPECT_EQ(r.max, 197.0f);
}

TEST(ImageStats, RegionStatisticsCoverOnlyTheRectangle) {
    // Texels x 2..4, y 3..4 (corners given in reverse order): values 33..35 and 43..45.
    PixelRect const r = rectFromCorners({4, 4}, {2, 3});
    EXPECT_EQ(r.min, glm::ivec2(2, 3));
    EXPECT_EQ(r.max, glm::ivec2(5, 5));
    ImageStats const s = imageStats(ramp100(), 0x1, r);
    EXPECT_EQ(s.pixels, 6);
    EXPECT_EQ(s.shown.min, 33.0f);
    EXPECT_EQ(s.shown.max, 45.0f);
    EXPECT_DOUBLE_EQ(s.shown.mean, 39.0);
    // Clipped to the image; an empty rectangle means the whole image.
    EXPECT_EQ(imageStats(ramp100(), 0x1, PixelRect{{8, 8}, {20, 20}}).pixels, 4);
    EXPECT_EQ(imageStats(ramp100(), 0x1, PixelRect{{3, 3}, {3, 3}}).pixels, 100);
}

TEST(ImageStats, SkipRuleLeavesBackgroundOut) {
    // RGBA with alpha 0 on the first pixel: ZeroAlpha leaves it out.
    FloatImage img{2, 1, 4, {-5.0f, 0.0f, 0.0f, 0.0f, 2.0f, 3.0f, 4.0f, 1.0f}};
    ImageStats const s = imageStats(img, 0x1, {}, RangeSkip::ZeroAlpha);
    EXPECT_EQ(s.pixels, 1);
    EXPECT_EQ(s.shown.min, 2.0f);
    EXPECT_EQ(s.negativePixels, 0);
}

TEST(ImageStats, ClipCountsAgainstBlackAndWhitePoints) {
    ClipCounts const c = clipCounts(ramp100(), 0x1, 10.0f, 90.0f);
    EXPECT_EQ(c.below, 9);   // 1..9
    EXPECT_EQ(c.above, 10);  // 91..100
    EXPECT_EQ(c.inside, 81);
}

TEST(ImageStats, DiffFindsTheChangedTexelsAndTheLargest) {
    FloatImage const pinned = ramp100();
    FloatImage current = pinned;
    current.pixels[23] += 0.5f;  // texel (3, 2)
    current.pixels[77] -= 4.0f;  // texel (7, 7): the largest
    current.pixels[90] = kNaN;   // texel (0, 9)
    DiffStats const d = diffImages(current, pinned, 0x1, 0.25f);
    ASSERT_TRUE(d.comparable);
    EXPECT_EQ(d.pixels, 100);
    EXPECT_EQ(d.max, 4.0f);
    EXPECT_EQ(d.maxAt, glm::ivec2(7, 7));
    EXPECT_EQ(d.overThreshold, 2);
    EXPECT_EQ(d.nanPixels, 1);
    EXPECT_DOUBLE_EQ(d.mean, 4.5 / 99.0);
    EXPECT_EQ(d.diff.at(3, 2, 0), 0.5f);
    EXPECT_EQ(d.diff.at(1, 1, 0), 0.0f);
    EXPECT_TRUE(std::isnan(d.diff.at(0, 9, 0)));
    // Relative: 4 / 78 at (7, 7), 0.5 / 24 at (3, 2); only the first is above 5 %.
    DiffStats const rel = diffImages(current, pinned, 0x1, 0.05f, DiffMode::Relative);
    EXPECT_FLOAT_EQ(rel.max, 4.0f / 78.0f);
    EXPECT_EQ(rel.overThreshold, 1);
    // Different sizes cannot be compared.
    FloatImage small{2, 2, 1, {0, 0, 0, 0}};
    EXPECT_FALSE(diffImages(small, pinned, 0x1, 0.0f).comparable);
}

TEST(ImageStats, DiffTakesTheLargestOfTheShownChannels) {
    FloatImage const a{1, 1, 3, {1.0f, 2.0f, 3.0f}};
    FloatImage const b{1, 1, 3, {1.5f, 0.0f, 3.0f}};
    EXPECT_EQ(diffImages(a, b, 0x7, 0.0f).max, 2.0f);
    EXPECT_EQ(diffImages(a, b, 0x1, 0.0f).max, 0.5f);  // green hidden
}
