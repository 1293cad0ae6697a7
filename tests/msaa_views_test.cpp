// The editor's MSAA views as plain values (ui/model/msaa_views.h): the Pipeline window's greyed
// sample counts from a faked GlCaps, the overlay's and the heat map's colours, the sample selector.
#include "model/msaa_views.h"
#include "core/heat_scale.h"
#include "gl/caps.h"
#include "gl/sample_limit.h"

#include <gtest/gtest.h>

using namespace gbl;
using namespace gbl::ui;

namespace {

MsaaReasons reasonsFor(GlCaps const& caps) {
    return msaaReasons([&](int n) { return caps.msaaUnavailableReason(n); });
}

// GBL_MAX_SAMPLES=n fakes a smaller driver (ui_msaa.sh greys 8 so); a bad value is one sentence
// and leaves the limits as read.
TEST(MsaaViews, TheSampleLimitOverrideLowersTheLimitsOrSaysWhyNot) {
    GlCaps caps;
    caps.maxSamples = 32;
    caps.maxColorTextureSamples = 16;
    caps.maxDepthTextureSamples = 2;
    EXPECT_EQ(applySampleLimit(caps, nullptr), "");
    EXPECT_EQ(caps.maxMsaaSamples(), 2);
    caps.maxDepthTextureSamples = 16;
    EXPECT_EQ(applySampleLimit(caps, "4"), "");
    EXPECT_EQ(caps.maxSamples, 4);
    EXPECT_EQ(caps.maxColorTextureSamples, 4);
    EXPECT_EQ(caps.maxDepthTextureSamples, 4);
    EXPECT_EQ(reasonsFor(caps)[2], "");
    EXPECT_NE(reasonsFor(caps)[3].find("8 samples exceed"), std::string::npos);
    EXPECT_EQ(applySampleLimit(caps, "8"), "") << "never raises a limit";
    EXPECT_EQ(caps.maxSamples, 4);
    for (char const* bad : {"four", "0", "65", "4x", ""}) {
        EXPECT_EQ(applySampleLimit(caps, bad), std::string("GBL_MAX_SAMPLES=") + bad +
                                                   " is not a sample count from 1 to 64, so the driver's sample "
                                                   "limits are used");
        EXPECT_EQ(caps.maxMsaaSamples(), 4);
    }
}

TEST(MsaaViews, SampleCountsAboveTheDriversLimitAreGreyedWithTheReason) {
    GlCaps caps;
    caps.maxSamples = 4;
    caps.maxColorTextureSamples = 4;
    caps.maxDepthTextureSamples = 4;
    MsaaReasons const r = reasonsFor(caps);
    EXPECT_EQ(r[0], "") << "off is always offered";
    EXPECT_EQ(r[1], "");
    EXPECT_EQ(r[2], "");
    EXPECT_EQ(r[3],
              "8 samples exceed this driver's limit (GL_MAX_SAMPLES 4, GL_MAX_COLOR_TEXTURE_SAMPLES 4, "
              "GL_MAX_DEPTH_TEXTURE_SAMPLES 4)");
    // The smallest of the three limits decides: depth textures of 2 samples grey 4 and 8.
    caps.maxSamples = caps.maxColorTextureSamples = 8;
    caps.maxDepthTextureSamples = 2;
    MsaaReasons const depth = reasonsFor(caps);
    EXPECT_EQ(depth[1], "");
    EXPECT_NE(depth[2].find("4 samples exceed"), std::string::npos) << depth[2];
    EXPECT_NE(depth[3].find("GL_MAX_DEPTH_TEXTURE_SAMPLES 2"), std::string::npos) << depth[3];
    // A context without multisample textures (all limits 0) greys every count, never off.
    MsaaReasons const none = reasonsFor(GlCaps{});
    EXPECT_EQ(none[0], "");
    for (std::size_t i = 1; i < none.size(); ++i) EXPECT_FALSE(none[i].empty()) << kMsaaNames[i];
}

TEST(MsaaViews, TheOverlayTintsComplexPixelsOnly) {
    FloatImage const mask{3, 1, 1, {0.0f, 1.0f, 0.4f}};
    std::vector<std::uint8_t> const rgba = complexOverlayRgba(mask);
    ASSERT_EQ(rgba.size(), 12u);
    EXPECT_EQ(rgba[3], 0) << "a simple pixel is clear";
    EXPECT_EQ(rgba[4], 255);
    EXPECT_EQ(rgba[5], 0);
    EXPECT_EQ(rgba[6], 255);
    EXPECT_GT(rgba[7], 0) << "a complex pixel is magenta";
    EXPECT_EQ(rgba[11], 0) << "below 0.5 is simple";
    EXPECT_DOUBLE_EQ(maskShare(mask), 1.0 / 3.0);
    FloatImage const counts{4, 1, 1, {1.0f, 2.0f, 4.0f, 1.0f}};
    FloatImage const fromCounts = complexFromCounts(counts);
    EXPECT_EQ(fromCounts.pixels, (std::vector<float>{0.0f, 1.0f, 1.0f, 0.0f}));
    EXPECT_DOUBLE_EQ(maskShare(fromCounts), 0.5);
    EXPECT_DOUBLE_EQ(maskShare(FloatImage{}), 0.0);
}

TEST(MsaaViews, TheHeatMapUsesTheSharedHeatScale) {
    FloatImage const counts{5, 1, 1, {1.0f, 2.0f, 3.0f, 4.0f, 8.0f}};
    std::vector<std::uint8_t> const rgba = samplesHeatRgba(counts);
    ASSERT_EQ(rgba.size(), 20u);
    int const bins[5] = {1, 2, 2, 3, 4};  // 1, 2-3, 2-3, 4-7, 8-15
    for (int i = 0; i < 5; ++i) {
        auto const& c = kHeatBinColors[std::size_t(bins[i])];
        for (int k = 0; k < 3; ++k) EXPECT_EQ(rgba[std::size_t(i * 4 + k)], c[std::size_t(k)]) << "count " << i;
        EXPECT_EQ(rgba[std::size_t(i * 4 + 3)], 255);
    }
}

TEST(MsaaViews, TheSampleSelectorStaysInRange) {
    EXPECT_EQ(sampleChoiceLabel(-1), "all");
    EXPECT_EQ(sampleChoiceLabel(3), "sample 3");
    EXPECT_EQ(clampSample(1, 4), 1);
    EXPECT_EQ(clampSample(4, 4), -1) << "past the count: all";
    EXPECT_EQ(clampSample(1, 0), -1) << "msaa off: all";
    EXPECT_EQ(viewerSampleSlot(ViewerKind::Position), GBufferSlot::Position);
    EXPECT_EQ(viewerSampleSlot(ViewerKind::Specular), GBufferSlot::AlbedoSpec);
    EXPECT_FALSE(viewerSampleSlot(ViewerKind::Depth).has_value());
    EXPECT_FALSE(viewerSampleSlot(ViewerKind::Lighting).has_value());
}

}  // namespace
