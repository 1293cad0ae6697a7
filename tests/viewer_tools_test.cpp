// Viewer tools' model: the depth viewer's values, the 1-99 % fit and region fit requests, pin and diff.
#include "model/viewer_tools.h"

#include "core/depth.h"
#include "model/colormap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace gbl;
using namespace gbl::ui;

namespace {
// 10x10 RGBA: R = 1..100 row by row, alpha 1 (drawn everywhere).
FloatImage positions() {
    FloatImage img{10, 10, 4, {}};
    for (int i = 0; i < 100; ++i) img.pixels.insert(img.pixels.end(), {float(i + 1), 0.0f, 0.0f, 1.0f});
    return img;
}
}  // namespace

TEST(ViewerTools, DepthValuesAreLinearisedAndKeepTheStoredDepth) {
    ViewerState v;
    v.kind = ViewerKind::Depth;
    v.linearDepth = true;
    FloatImage const depth{2, 1, 1, {0.5f, 1.0f}};
    FloatImage const values = viewerValues(v, depth, 0.1f, 100.0f);
    ASSERT_EQ(values.channels, 4);
    EXPECT_FLOAT_EQ(values.at(0, 0, 0), linearDepth(0.5f, 0.1f, 100.0f));
    EXPECT_EQ(values.at(0, 0, 1), 0.5f);  // stored depth, for the raw bits
    EXPECT_EQ(values.at(0, 0, 3), 1.0f);
    EXPECT_EQ(values.at(1, 0, 3), 0.0f);  // cleared depth: background
    // Background takes no part in the statistics.
    EXPECT_EQ(imageStats(values, viewerStatsMask(v), {}, viewerSkip(v.kind)).pixels, 1);
}

TEST(ViewerTools, PercentileFitRequestSetsThePointsAndIsCleared) {
    ViewerState v;
    v.kind = ViewerKind::Position;
    v.channelMask = 0x1;
    v.autoFit = true;
    v.percentileFitRequested = true;
    ViewerData d;
    FloatImage img = positions();
    img.pixels[0] = std::numeric_limits<float>::quiet_NaN();  // texel 0's R: not a value
    setViewerValues(v, d, img, 7);
    EXPECT_FALSE(v.percentileFitRequested);
    EXPECT_FALSE(v.autoFit);
    // 99 values 2..100: rank ceil(0.99) = 1 is 2, rank ceil(98.01) = 99 is 100.
    EXPECT_EQ(v.rangeMin, 2.0f);
    EXPECT_EQ(v.rangeMax, 100.0f);
    EXPECT_EQ(d.stats.nanPixels, 1);
    EXPECT_EQ(d.frame, 7);
}

TEST(ViewerTools, RegionFitUsesTheRegionsMinAndMax) {
    ViewerState v;
    v.channelMask = 0x1;
    v.region = rectFromCorners({2, 3}, {4, 4});  // values 33..35, 43..45
    ViewerData d;
    setViewerValues(v, d, positions(), 1);
    EXPECT_EQ(d.regionStats.pixels, 6);
    v.regionFitRequested = true;
    updateViewerStats(v, d);
    EXPECT_FALSE(v.regionFitRequested);
    EXPECT_EQ(v.rangeMin, 33.0f);
    EXPECT_EQ(v.rangeMax, 45.0f);
}

TEST(ViewerTools, PinThenDiffShowsWhatChanged) {
    ViewerState v;
    v.channelMask = 0x1;
    v.pinRequested = true;
    ViewerData d;
    setViewerValues(v, d, positions(), 1);
    ASSERT_TRUE(d.pinned);
    EXPECT_FALSE(v.pinRequested);
    v.showDiff = true;
    FloatImage changed = positions();
    changed.pixels[(2 * 10 + 5) * 4] += 3.0f;  // texel (5, 2)
    setViewerValues(v, d, changed, 31);
    EXPECT_TRUE(d.diff.comparable);
    EXPECT_EQ(d.diff.max, 3.0f);
    EXPECT_EQ(d.diff.maxAt, glm::ivec2(5, 2));
    EXPECT_EQ(d.pinnedFrame, 1);
    // The heat map: black where equal, the top of turbo at the largest difference.
    std::vector<std::uint8_t> const rgba = diffHeatmap(d.diff, d.diff.max);
    ASSERT_EQ(rgba.size(), 400u);
    EXPECT_EQ(rgba[0], 0);
    std::size_t const at = (2 * 10 + 5) * 4;
    EXPECT_EQ(rgba[at], 144);  // turbo(1) = (0.566, 0.050, 0.000) -> 144, 13, 0
    EXPECT_EQ(rgba[at + 1], 13);
}

TEST(ViewerTools, SyncCopiesZoomAndPanToEveryViewer) {
    GBufferPanelState p;
    p.viewers[2].zoom = 4.0f;
    p.viewers[2].center = {0.25f, 0.75f};
    syncViewers(p, 2);
    for (auto const& v : p.viewers) {
        EXPECT_EQ(v.zoom, 4.0f);
        EXPECT_EQ(v.center, glm::vec2(0.25f, 0.75f));
    }
}

TEST(ViewerTools, StoredFloatTextShowsTheValueAndItsBits) {
    EXPECT_EQ(storedFloatText(0.5f), "0.5 (bits 0x3f000000)");
    EXPECT_EQ(storedFloatText(1.0f), "1 (bits 0x3f800000)");
    // A depth near the far plane: 9 digits tell neighbouring floats apart, the bits show the step.
    EXPECT_EQ(storedFloatText(std::nextafter(1.0f, 0.0f)), "0.99999994 (bits 0x3f7fffff)");
    EXPECT_EQ(storedFloatText(-0.0f), "-0 (bits 0x80000000)");
}

TEST(ViewerTools, LitPinHoldsTheFrameAndDiffsTheNextOne) {
    // 4x2 RGBA lit frames; the second changes one pixel's green by 0.25 and leaves alpha alone.
    FloatImage a{4, 2, 4, {}};
    for (int i = 0; i < 8; ++i) a.pixels.insert(a.pixels.end(), {0.5f, 1.0f, 2.0f, 1.0f});
    FloatImage b = a;
    b.pixels[(1 * 4 + 2) * 4 + 1] = 1.25f;  // texel (2, 1), green
    LitPin pin;
    EXPECT_FALSE(litPinDue(pin, 0));  // nothing asked for: no read-back
    pin.pinRequested = true;
    ASSERT_TRUE(litPinDue(pin, 0));
    setLitValues(pin, a, 3);
    EXPECT_FALSE(pin.pinRequested);
    ASSERT_TRUE(pin.pinned);
    EXPECT_EQ(pin.pinnedFrame, 3);
    EXPECT_EQ(pin.stats.shown.max, 2.0f);
    EXPECT_FALSE(pin.diff.comparable);  // the diff is not shown yet
    pin.showDiff = true;
    ASSERT_TRUE(litPinDue(pin, 4));  // turning the diff on computes it at once
    setLitValues(pin, a, 4);
    ASSERT_TRUE(pin.diff.comparable);
    EXPECT_EQ(pin.diff.max, 0.0f);
    EXPECT_FALSE(litPinDue(pin, 4 + kViewerDataInterval - 1));
    ASSERT_TRUE(litPinDue(pin, 4 + kViewerDataInterval));
    setLitValues(pin, b, 4 + kViewerDataInterval);
    ASSERT_TRUE(pin.diff.comparable);
    EXPECT_EQ(pin.diff.max, 0.25f);
    EXPECT_EQ(pin.diff.maxAt, glm::ivec2(2, 1));
    EXPECT_EQ(pin.diff.pixels, 8);
    EXPECT_EQ(pin.diff.overThreshold, 1);  // threshold 0: only the changed pixel is over
    EXPECT_EQ(pin.stats.channel[1].max, 1.25f);
    // The heat map of the lit diff is the viewers' one: black where equal, turbo's top at the max.
    std::vector<std::uint8_t> const rgba = diffHeatmap(pin.diff, pin.diff.max);
    EXPECT_EQ(rgba[0], 0);
    EXPECT_EQ(rgba[(1 * 4 + 2) * 4], 144);
}

TEST(ViewerTools, LitDiffThresholdAndModeApplyWithoutANewReadBack) {
    // Pinned: one pixel of 1.0 and one of 4.0; now: +0.5 on both (0.5 relative, 0.125 relative).
    FloatImage pinned{2, 1, 4, {1.0f, 1.0f, 1.0f, 1.0f, 4.0f, 4.0f, 4.0f, 1.0f}};
    FloatImage now{2, 1, 4, {1.5f, 1.5f, 1.5f, 1.0f, 4.5f, 4.5f, 4.5f, 1.0f}};
    LitPin pin;
    pin.pinRequested = true;
    setLitValues(pin, pinned, 1);
    pin.showDiff = true;
    setLitValues(pin, now, 2);
    ASSERT_TRUE(pin.diff.comparable);
    EXPECT_EQ(pin.diff.overThreshold, 2);
    EXPECT_FALSE(updateLitDiff(pin));  // nothing changed: nothing recomputed
    pin.diffThreshold = 0.25f;
    EXPECT_FALSE(litPinDue(pin, 3));       // no read-back is due ...
    ASSERT_TRUE(updateLitDiff(pin));       // ... yet the new threshold counts at once
    EXPECT_EQ(pin.diff.overThreshold, 2);  // both differ by 0.5 > 0.25
    pin.diffMode = DiffMode::Relative;
    ASSERT_TRUE(updateLitDiff(pin));
    EXPECT_EQ(pin.diff.overThreshold, 1);  // 0.5 / 1 = 0.5 is over, 0.5 / 4 = 0.125 is not
    EXPECT_FLOAT_EQ(pin.diff.max, 0.5f);
    EXPECT_EQ(pin.frame, 2);  // the values are the read-back's of frame 2
}

TEST(ViewerTools, StencilValuesAreIntegersEveryPixelCounts) {
    ViewerState v = GBufferPanelState::defaultViewers()[4];
    v.rangeMin = 0.2f;
    v.rangeMax = 0.9f;
    setShowStencil(v, true);
    EXPECT_EQ(viewerAttachment(v), Attachment::Stencil);
    EXPECT_EQ(v.rangeMin, 0.0f);  // the stencil's own range
    EXPECT_EQ(v.rangeMax, 255.0f);
    FloatImage const stencil{3, 1, 1, {0.0f, 7.0f, 255.0f}};
    FloatImage const values = viewerValues(v, stencil, 0.1f, 100.0f);
    ASSERT_EQ(values.channels, 4);
    EXPECT_EQ(values.at(1, 0, 0), 7.0f);
    EXPECT_EQ(values.at(0, 0, 3), 1.0f);  // no background: a 0 is a value
    ImageStats const s = imageStats(values, viewerStatsMask(v), {}, viewerSkip(v.kind));
    EXPECT_EQ(s.pixels, 3);
    EXPECT_EQ(s.shown.max, 255.0f);
    // Another key than the depth's, so switching rereads.
    ViewerState depth = v;
    setShowStencil(depth, false);
    EXPECT_NE(viewerValuesKey(depth), viewerValuesKey(v));
    EXPECT_EQ(depth.rangeMin, 0.2f);  // the depth's range came back
    EXPECT_EQ(depth.rangeMax, 0.9f);
    EXPECT_EQ(viewerAttachment(depth), Attachment::Depth);
}

TEST(ViewerTools, StencilPictureIsTheColormapOfTheRemappedIntegers) {
    ViewerState v = GBufferPanelState::defaultViewers()[4];
    setShowStencil(v, true);
    FloatImage const values = viewerValues(v, FloatImage{4, 1, 1, {0.0f, 51.0f, 255.0f, 200.0f}}, 0.1f, 100.0f);
    // Grey over 0..255: the byte is the integer itself.
    std::vector<std::uint8_t> grey = viewerPicture(v, values);
    ASSERT_EQ(grey.size(), 16u);
    EXPECT_EQ(grey[0], 0);
    EXPECT_EQ(grey[4], 51);
    EXPECT_EQ(grey[5], 51);
    EXPECT_EQ(grey[8], 255);
    EXPECT_EQ(grey[11], 255);  // opaque
    // Turbo over 0..100, clipping on: 51 is turbo(0.51), 255 and 200 are above white (red).
    v.colormap = Colormap::Turbo;
    v.rangeMax = 100.0f;
    v.overlays = kOverlayClip;
    std::vector<std::uint8_t> const turbo = viewerPicture(v, values);
    glm::vec3 const expected = colormap(Colormap::Turbo, 0.51f);
    EXPECT_EQ(turbo[4], std::uint8_t(std::lround(expected.r * 255.0f)));
    EXPECT_EQ(turbo[5], std::uint8_t(std::lround(expected.g * 255.0f)));
    EXPECT_EQ(turbo[8], 255);
    EXPECT_EQ(turbo[9], 0);
    EXPECT_EQ(turbo[10], 0);
    EXPECT_EQ(turbo[12], 255);
    EXPECT_EQ(turbo[13], 0);
}

TEST(ViewerTools, ShownTexelColourMarksNaNAndInfAsTheShaderDoes) {
    ViewerState v;
    v.kind = ViewerKind::Position;
    v.channelMask = 0x7;
    v.rangeMin = 0.0f;
    v.rangeMax = 2.0f;
    float const nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    FloatImage const img{3, 1, 4, {1.0f, 0.5f, 2.0f, 1.0f, nan, 0.0f, 0.0f, 1.0f, 0.0f, inf, 0.0f, 1.0f}};
    EXPECT_EQ(shownTexelColour(v, img, 0, 0), glm::vec3(0.5f, 0.25f, 1.0f));  // remapped, per channel
    v.overlays = kOverlayNaN | kOverlayInf;
    EXPECT_EQ(shownTexelColour(v, img, 1, 0), glm::vec3(1.0f, 0.0f, 1.0f));   // magenta
    EXPECT_EQ(shownTexelColour(v, img, 2, 0), glm::vec3(0.0f, 1.0f, 0.0f));   // green
    EXPECT_EQ(shownTexelColour(v, img, 0, 0), glm::vec3(0.5f, 0.25f, 1.0f));  // finite: unchanged
}

TEST(ViewerTools, ViewportToolsFollowTheViewportsView) {
    ViewportTools tools;
    EXPECT_FALSE(followViewportView(tools, DebugView::Final));
    EXPECT_FALSE(followViewportView(tools, DebugView::Heatmap));
    // The lit frame: its HDR values before the tonemap, RGB, every pixel counted.
    ASSERT_TRUE(followViewportView(tools, DebugView::Lighting));
    EXPECT_EQ(tools.viewer.kind, ViewerKind::Lighting);
    EXPECT_EQ(tools.viewer.channelMask, 0x7u);
    EXPECT_EQ(viewerAttachment(tools.viewer), Attachment::Lighting);
    EXPECT_EQ(viewerDebugView(tools.viewer), DebugView::Lighting);
    EXPECT_EQ(viewerSkip(ViewerKind::Lighting), RangeSkip::None);
    EXPECT_EQ(viewerKindName(ViewerKind::Lighting), "lighting");
    EXPECT_EQ(viewerKindName(ViewerKind::Depth), "depth");
    ASSERT_TRUE(followViewportView(tools, DebugView::Albedo));
    EXPECT_EQ(tools.viewer.kind, ViewerKind::Albedo);
    EXPECT_EQ(tools.viewer.channelMask, 0x7u);
    tools.viewer.region = PixelRect{{0, 0}, {2, 2}};
    tools.viewer.colormap = Colormap::Viridis;
    tools.data.frame = 5;
    ASSERT_TRUE(followViewportView(tools, DebugView::DepthLinear));
    EXPECT_EQ(tools.viewer.kind, ViewerKind::Depth);
    EXPECT_TRUE(tools.viewer.linearDepth);
    EXPECT_EQ(tools.viewer.channelMask, 0x1u);
    EXPECT_FALSE(tools.viewer.region);                    // another attachment: the region was the albedo's
    EXPECT_EQ(tools.data.frame, -1);                      // and so were the values
    EXPECT_EQ(tools.viewer.colormap, Colormap::Viridis);  // settings stay
    ASSERT_TRUE(followViewportView(tools, DebugView::Depth));
    EXPECT_FALSE(tools.viewer.linearDepth);
    EXPECT_EQ(tools.viewer.lastFitFrame, -1);
}

TEST(ViewerTools, ReadableRangeLeavesOutTheOutliersTheBackgroundAndNonFiniteValues) {
    ViewerState v;
    v.kind = ViewerKind::Position;
    v.channelMask = 0x1;
    FloatImage img = positions();  // R = 1..100
    // A NaN and an Inf on drawn pixels (R = 1, 2) and a background pixel (alpha 0) far outside
    // (R = 100): none counts.
    img.pixels[0] = std::numeric_limits<float>::quiet_NaN();
    img.pixels[4] = std::numeric_limits<float>::infinity();
    img.pixels[396] = -1000.0f;
    img.pixels[399] = 0.0f;
    ValueRange const r = readableRange(v, img);
    EXPECT_EQ(r.samples, 97);  // 100 less NaN, Inf and the background
    // Nearest rank over 3..99: the 1st percentile is the 1st value, the 99th the 97th of 97.
    EXPECT_EQ(r.min, 3.0f);
    EXPECT_EQ(r.max, 99.0f);
    // The lit frame keeps its darkest values (0th percentile) and counts every pixel.
    v.kind = ViewerKind::Lighting;
    FloatImage lit = positions();
    EXPECT_EQ(readableRange(v, lit).min, 1.0f);
    EXPECT_EQ(readableRange(v, lit).max, 99.0f);
}

// The G-buffer window's viewers: auto-fit takes the readable 1-99 % range, as the viewport's do, so
// one far outlier no longer squeezes the picture; the Fit button still takes min..max.
TEST(ViewerTools, StripViewersAutoFitTheReadableRangeAndFitTheWholeRangeOnAsk) {
    ViewerState v;
    v.kind = ViewerKind::Position;
    v.channelMask = 0x1;
    FloatImage img = positions();  // R = 1..100
    img.pixels[396] = 5000.0f;     // one outlier on a drawn pixel (R of texel 99)
    ValueRange const automatic = stripViewerRange(v, img, false, 0.1f, 100.0f);
    EXPECT_EQ(automatic.min, 1.0f);
    EXPECT_EQ(automatic.max, 99.0f);
    ValueRange const asked = stripViewerRange(v, img, true, 0.1f, 100.0f);
    EXPECT_EQ(asked.min, 1.0f);
    EXPECT_EQ(asked.max, 5000.0f);

    // Depth: raw window depths; the far plane is background either way, auto-fit is in linear
    // distance when the viewer linearises.
    v = ViewerState{};
    v.kind = ViewerKind::Depth;
    v.linearDepth = true;
    FloatImage depth{100, 1, 1, {}};
    for (int i = 0; i < 99; ++i) depth.pixels.push_back(0.9f + 0.0009f * float(i));
    depth.pixels.push_back(1.0f);
    ValueRange const linear = stripViewerRange(v, depth, false, 0.1f, 100.0f);
    EXPECT_EQ(linear.samples, 99);
    EXPECT_NEAR(linear.min, linearDepth(0.9f, 0.1f, 100.0f), 1e-4f);
    EXPECT_LT(linear.max, linearDepth(0.9f + 0.0009f * 98.0f, 0.1f, 100.0f) + 1e-3f);
    EXPECT_GT(linear.max, linear.min);
    ValueRange const whole = stripViewerRange(v, depth, true, 0.1f, 100.0f);
    EXPECT_EQ(whole.samples, 99);
    EXPECT_NEAR(whole.max, linearDepth(0.9f + 0.0009f * 98.0f, 0.1f, 100.0f), 1e-3f);

    // The stencil's integers fit whole, one step wide at least.
    v.showStencil = true;
    FloatImage const stencil{4, 1, 1, {3.0f, 3.0f, 3.0f, 3.0f}};
    ValueRange const marks = stripViewerRange(v, stencil, false, 0.1f, 100.0f);
    EXPECT_EQ(marks.min, 3.0f);
    EXPECT_EQ(marks.max, 4.0f);
}

TEST(ViewerTools, AutoFitRefitsAtOnceWhenTheValuesMeanSomethingElse) {
    ViewerState v = ViewportTools::defaultViewer();
    v.kind = ViewerKind::Depth;
    v.linearDepth = false;
    ViewerData d;
    glm::vec2 const planes(0.1f, 200.0f);
    EXPECT_TRUE(autoFitDue(v, d, planes, 10, false));  // never fitted
    v.lastFitFrame = 10;
    d.autoFitFor = std::make_pair(viewerValuesKey(v), planes);
    EXPECT_FALSE(autoFitDue(v, d, planes, 11, false));
    EXPECT_FALSE(autoFitDue(v, d, planes, 69, true));  // its next turn is 60 frames on...
    EXPECT_TRUE(autoFitDue(v, d, planes, 70, true));   // ... on a rendered frame
    EXPECT_FALSE(autoFitDue(v, d, planes, 70, false));
    // Raw window depth to linear depth: the range of one is meaningless for the other.
    v.linearDepth = true;
    EXPECT_TRUE(autoFitDue(v, d, planes, 11, false));
    d.autoFitFor = std::make_pair(viewerValuesKey(v), planes);
    EXPECT_FALSE(autoFitDue(v, d, planes, 11, false));
    // A new far plane moves every linear depth.
    EXPECT_TRUE(autoFitDue(v, d, glm::vec2(0.1f, 5000.0f), 11, false));
    // Auto-fit off: never.
    v.autoFit = false;
    EXPECT_FALSE(autoFitDue(v, d, glm::vec2(0.1f, 5000.0f), 11, true));
}
