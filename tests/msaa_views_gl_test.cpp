// The editor's msaa views read back (docs/msaa.md, issue 47): one sample of an attachment, whole or
// a rectangle of it, and the samples-that-differ counts, on the default scene at 4 samples and
// 160x90. The counts are checked against the edges pass's own complex mask and against counts of
// the whole samples read in the test; the rectangle reads against the whole ones and the export.
#include "core/msaa_samples.h"
#include "frame_export.h"
#include "gl_fixture.h"
#include "image/image_io.h"
#include "run_command.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

using namespace gbl;

namespace {

constexpr int kW = 160, kH = 90, kSamples = 4;

class MsaaViewsGlTest : public test::CourtyardGlTest {
protected:
    MsaaViewsGlTest() : CourtyardGlTest(kW, kH) {}

    FrameStats renderMsaa(MsaaLighting lighting = MsaaLighting::Edges) {
        PipelineSettings s;
        s.lightCubes = false;
        s.msaa = Msaa::X4;
        s.msaaLighting = lighting;
        FrameStats const st = renderer_->render({camera_, lights_, s, true});
        EXPECT_EQ(st.msaaUsed, Msaa::X4) << st.fallbackReason;
        EXPECT_EQ(st.glErrors, 0u);
        return st;
    }
};

TEST_F(MsaaViewsGlTest, ARectangleOfASampleEqualsThoseTexelsOfTheWholeSample) {
    renderMsaa();
    ASSERT_EQ(renderer_->msaaSampleCount(), kSamples);
    for (GBufferSlot slot : {GBufferSlot::Position, GBufferSlot::AlbedoSpec})
        for (int k : {0, 3}) {
            FloatImage const whole = renderer_->readMsaaSample(slot, k);
            ASSERT_EQ(whole.width, kW);
            // A band across the middle and a single pixel, top-left origin like the whole read.
            FloatImage const band = renderer_->readMsaaSample(slot, k, {0, 40, kW, 17});
            ASSERT_EQ(band.width, kW);
            ASSERT_EQ(band.height, 17);
            for (int y = 0; y < 17; ++y)
                for (int x = 0; x < kW; ++x)
                    for (int c = 0; c < 4; ++c) ASSERT_EQ(band.at(x, y, c), whole.at(x, y + 40, c)) << x << "," << y;
            FloatImage const one = renderer_->readMsaaSample(slot, k, {123, 7, 1, 1});
            ASSERT_EQ(one.pixels.size(), 4u);
            for (int c = 0; c < 4; ++c) EXPECT_EQ(one.at(0, 0, c), whole.at(123, 7, c));
        }
    // Clipped to the frame; outside it nothing.
    EXPECT_EQ(renderer_->readMsaaSample(GBufferSlot::Position, 0, {150, 80, 40, 40}).width, 10);
    EXPECT_TRUE(renderer_->readMsaaSample(GBufferSlot::Position, 0, {kW, 0, 4, 4}).pixels.empty());
    EXPECT_TRUE(renderer_->readMsaaSample(GBufferSlot::Depth, 0, {0, 0, 4, 4}).pixels.empty());
}

// What the viewers and the inspector read of sample k is what `render --msaa` exports as
// raw_<name>_s<k>.exr (exportFrame writes that set), texel for texel.
TEST_F(MsaaViewsGlTest, ASampleReadForTheViewersEqualsItsExport) {
    FrameStats const stats = renderMsaa();
    PipelineSettings s;
    s.lightCubes = false;
    s.msaa = Msaa::X4;
    s.msaaLighting = MsaaLighting::Edges;
    std::string const dir = test::freshTempDir("msaa_views_export");
    ASSERT_FALSE(exportFrame(*renderer_, {camera_, lights_, s, stats, scene_.triangleCount(), {}}, dir));
    for (auto const& [name, slot] :
         {std::pair{"position", GBufferSlot::Position}, std::pair{"albedo_spec", GBufferSlot::AlbedoSpec}}) {
        std::string const file = dir + "/raw_" + name + "_s1.exr";
        std::optional<FloatImage> const exported = readImage(file);
        ASSERT_TRUE(exported) << file;
        FloatImage const one = renderer_->readMsaaSample(slot, 1, {31, 62, 1, 1});
        ASSERT_EQ(exported->width, kW);
        ASSERT_EQ(exported->channels, 4);
        ASSERT_EQ(one.pixels.size(), 4u);
        for (int c = 0; c < 4; ++c) EXPECT_EQ(one.at(0, 0, c), exported->at(31, 62, c)) << name << " channel " << c;
        EXPECT_EQ(renderer_->readMsaaSample(slot, 1).pixels, exported->pixels) << name;
    }
}

TEST_F(MsaaViewsGlTest, SamplesDifferAtSilhouettesAndAgreeInside) {
    renderMsaa();
    std::array<FloatImage, kSamples> pos;
    for (int k = 0; k < kSamples; ++k) pos[std::size_t(k)] = renderer_->readMsaaSample(GBufferSlot::Position, k);
    // Each sample is its own: at silhouettes sample 3 holds another surface than sample 0 (a copy
    // of sample 0 four times would never differ); inside a surface they agree.
    int differ = 0, drawnEverywhere = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            float d = 0.0f;
            for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(pos[0].at(x, y, c) - pos[3].at(x, y, c)));
            differ += d > 0.1f;  // a tenth of a unit: another surface, not the same one a subpixel away
            drawnEverywhere += pos[0].at(x, y, 3) != 0.0f && pos[3].at(x, y, 3) != 0.0f;
        }
    EXPECT_GT(differ, 0);
    EXPECT_LT(differ, kW * kH / 4);
    EXPECT_GT(drawnEverywhere, kW * kH / 4);
}

// The heat map's counts are 1 exactly where the edges pass left a pixel simple (the same test,
// msaa_edges.glsl on the GPU, msaaSameSurface on the CPU); at a few pixels they equal the count of
// the samples read whole here.
TEST_F(MsaaViewsGlTest, DistinctSampleCountsMatchTheComplexMaskAndTheWholeSamples) {
    FrameStats const st = renderMsaa(MsaaLighting::Edges);
    FloatImage const counts = renderer_->msaaDistinctSampleCounts(camera_.position);
    FloatImage const mask = renderer_->readAttachment(Attachment::ComplexPixels);
    ASSERT_EQ(counts.width, kW);
    ASSERT_EQ(counts.height, kH);
    ASSERT_EQ(counts.channels, 1);
    int mismatches = 0, complex = 0, histogram[kSamples + 1] = {};
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            int const n = int(counts.at(x, y, 0));
            ASSERT_GE(n, 1);
            ASSERT_LE(n, kSamples);
            ++histogram[n];
            complex += n >= 2;
            mismatches += (n >= 2) != (mask.at(x, y, 0) > 0.5f);
        }
    // The GPU and the CPU compute the eye distance and the normals' dot product in their own float
    // order, so a sample just at a threshold may fall on either side: allow 0.5 % of the pixels.
    EXPECT_LE(mismatches, kW * kH / 200) << "complex " << complex;
    EXPECT_GT(complex, kW * kH / 100) << "silhouettes and the background edge are complex";
    EXPECT_LT(complex, kW * kH / 2) << "the courtyard's flat walls and floor are simple";
    ASSERT_TRUE(st.complexPixelShare.has_value());
    EXPECT_NEAR(double(complex) / (kW * kH), *st.complexPixelShare, 0.005);
    EXPECT_GT(histogram[1], 0);
    EXPECT_GT(histogram[2], 0);

    std::array<std::array<FloatImage, 3>, kSamples> whole;
    for (int k = 0; k < kSamples; ++k) {
        whole[std::size_t(k)][0] = renderer_->readMsaaSample(GBufferSlot::Position, k);
        whole[std::size_t(k)][1] = renderer_->readMsaaSample(GBufferSlot::Normal, k);
        whole[std::size_t(k)][2] = renderer_->readMsaaSample(GBufferSlot::AlbedoSpec, k);
    }
    auto const px = [&](int s, int k, int x, int y) {
        FloatImage const& im = whole[std::size_t(k)][std::size_t(s)];
        return glm::vec4(im.at(x, y, 0), im.at(x, y, 1), im.at(x, y, 2), im.at(x, y, 3));
    };
    int checked = 0, checkedComplex = 0;
    for (int y = 3; y < kH; y += 7)
        for (int x = 5; x < kW; x += 11) {
            std::array<MsaaSampleValues, kSamples> s;
            for (int k = 0; k < kSamples; ++k) s[std::size_t(k)] = {px(0, k, x, y), px(1, k, x, y), px(2, k, x, y)};
            int const expected = msaaDistinctSamples(s, camera_.position);
            EXPECT_EQ(int(counts.at(x, y, 0)), expected) << "pixel " << x << "," << y;
            ++checked;
            checkedComplex += expected >= 2;
        }
    EXPECT_GT(checked, 100);
    EXPECT_GT(checkedComplex, 0) << "the grid of pixels meets some edge";
}

TEST_F(MsaaViewsGlTest, WithoutAnMsaaFrameThereIsNothingToRead) {
    EXPECT_EQ(renderer_->msaaSampleCount(), 0);
    EXPECT_TRUE(renderer_->msaaDistinctSampleCounts(camera_.position).pixels.empty());
    EXPECT_TRUE(renderer_->readMsaaSample(GBufferSlot::Normal, 0, {0, 0, 8, 8}).pixels.empty());
}

}  // namespace
