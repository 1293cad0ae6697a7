// The editor's msaa views read back (docs/msaa.md, issue 47), on the default scene at 4 samples and
// 160x90: one sample of an attachment as stored, whole or a rectangle of it, against the whole ones
// and the export; and in every G-buffer layout, a sample decoded for the viewers and the inspector
// (Renderer::readMsaaDecodedSample) against its raw sample (what export writes as
// raw_<name>_s<k>.exr) decoded on the CPU (core/gbuffer_read_cpu.h), and the samples-that-differ
// counts (the decode pass's counts variant) against the edges pass's mask and the CPU count
// (core/msaa_samples.h) of the decoded samples.
#include "core/gbuffer_read_cpu.h"
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
    // The depth's samples: one channel, the window depth (background 1, the courtyard nearer).
    FloatImage const depth = renderer_->readMsaaSample(GBufferSlot::Depth, 2, {0, 0, 4, 4});
    ASSERT_EQ(depth.channels, 1);
    ASSERT_EQ(depth.pixels.size(), 16u);
    EXPECT_TRUE(renderer_->readMsaaDecodedSample(GBufferSlot::Depth, 0, {0, 0, 4, 4}).pixels.empty());
}

// Sample k as stored (what the decoded samples are checked against below) is what `render --msaa`
// exports as raw_<name>_s<k>.exr (exportFrame writes that set), texel for texel, the depth too.
TEST_F(MsaaViewsGlTest, ASampleReadEqualsItsExport) {
    FrameStats const stats = renderMsaa();
    PipelineSettings s;
    s.lightCubes = false;
    s.msaa = Msaa::X4;
    s.msaaLighting = MsaaLighting::Edges;
    std::string const dir = test::freshTempDir("msaa_views_export");
    ASSERT_FALSE(exportFrame(*renderer_, {camera_, lights_, s, stats, scene_.triangleCount(), {}}, dir));
    for (auto const& [name, slot] :
         {std::pair{"position", GBufferSlot::Position}, std::pair{"albedo_spec", GBufferSlot::AlbedoSpec},
          std::pair{"depth", GBufferSlot::Depth}}) {
        std::string const file = dir + "/raw_" + name + "_s1.exr";
        std::optional<FloatImage> const exported = readImage(file);
        ASSERT_TRUE(exported) << file;
        FloatImage const one = renderer_->readMsaaSample(slot, 1, {31, 62, 1, 1});
        int const channels = slot == GBufferSlot::Depth ? 1 : 4;
        ASSERT_EQ(exported->width, kW);
        ASSERT_EQ(exported->channels, channels);
        ASSERT_EQ(one.pixels.size(), std::size_t(channels));
        for (int c = 0; c < channels; ++c)
            EXPECT_EQ(one.at(0, 0, c), exported->at(31, 62, c)) << name << " channel " << c;
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

TEST_F(MsaaViewsGlTest, WithoutAnMsaaFrameThereIsNothingToRead) {
    EXPECT_EQ(renderer_->msaaSampleCount(), 0);
    EXPECT_TRUE(renderer_->msaaDistinctSampleCounts(camera_.position).pixels.empty());
    EXPECT_TRUE(renderer_->readMsaaSample(GBufferSlot::Normal, 0, {0, 0, 8, 8}).pixels.empty());
    EXPECT_TRUE(renderer_->readMsaaDecodedSample(GBufferSlot::Normal, 0, {0, 0, 8, 8}).pixels.empty());
    EXPECT_TRUE(renderer_->msaaSamplePositions().empty());
}

glm::vec4 texel(FloatImage const& im, int x, int y) {
    return {im.at(x, y, 0), im.at(x, y, 1), im.at(x, y, 2), im.at(x, y, 3)};
}

// One frame of `layout`: its samples decoded against their raw values decoded on the CPU, then its
// counts.
void checkLayout(Renderer& renderer, Camera const& camera, std::vector<PointLight> const& lights,
                 GBufferLayout layout) {
    GBufferLayoutDesc const& desc = layoutDesc(layout);
    PipelineSettings s;
    s.lightCubes = false;
    s.layout = layout;
    s.msaa = Msaa::X4;
    s.msaaLighting = MsaaLighting::Edges;
    FrameStats const stats = renderer.render({camera, lights, s, true});
    ASSERT_EQ(stats.msaaUsed, Msaa::X4) << stats.fallbackReason;
    std::vector<glm::vec2> const places = renderer.msaaSamplePositions();
    ASSERT_EQ(places.size(), std::size_t(kSamples));
    glm::mat4 const invViewProj = glm::inverse(camera.projection(float(kW) / float(kH)) * camera.view());
    bool const emissive = storesEmissiveAo(desc);
    // decoded[k]: position, normal, albedo + specular, emissive + ao of sample k, as the viewers read them.
    std::array<std::array<FloatImage, 4>, kSamples> decoded;
    int drawn = 0;
    for (int k = 0; k < kSamples; ++k) {
        std::array<FloatImage, 4>& d = decoded[std::size_t(k)];
        int slot = 0;
        for (GBufferSlot sl :
             {GBufferSlot::Position, GBufferSlot::Normal, GBufferSlot::AlbedoSpec, GBufferSlot::Emissive}) {
            d[std::size_t(slot)] = renderer.readMsaaDecodedSample(sl, k);
            ASSERT_EQ(d[std::size_t(slot++)].pixels.size(), std::size_t(kW * kH * 4));
        }
        // What export writes as raw_<name>_s<k>.exr (ASampleReadForTheViewersEqualsItsExport).
        FloatImage const rawNormal = renderer.readMsaaSample(GBufferSlot::Normal, k);
        FloatImage const rawAlbedo = renderer.readMsaaSample(GBufferSlot::AlbedoSpec, k);
        FloatImage const rawDepth = renderer.readMsaaSample(GBufferSlot::Depth, k);
        FloatImage const rawPosition =
            desc.storesPosition ? renderer.readMsaaSample(GBufferSlot::Position, k) : FloatImage{};
        FloatImage const rawEmissive = emissive ? renderer.readMsaaSample(GBufferSlot::Emissive, k) : FloatImage{};
        ASSERT_EQ(rawDepth.channels, 1);
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                // What the layout stores decides whether geometry was drawn: the position's w, or depth < 1.
                bool const covered =
                    desc.storesPosition ? rawPosition.at(x, y, 3) != 0.0f : rawDepth.at(x, y, 0) < 1.0f;
                drawn += covered;
                glm::vec4 const p = texel(d[0], x, y), n = texel(d[1], x, y);
                ASSERT_EQ(p.w, covered ? 1.0f : 0.0f) << x << "," << y << " sample " << k;
                ASSERT_EQ(n.w, p.w);
                ASSERT_EQ(texel(d[2], x, y), texel(rawAlbedo, x, y)) << "albedo is stored as read";
                ASSERT_EQ(texel(d[3], x, y), emissive ? texel(rawEmissive, x, y) : kNoEmissiveAo);
                if (!covered) continue;
                glm::vec3 const expectedN = decodeStoredNormal(desc.normalEncoding, texel(rawNormal, x, y));
                // The GPU and the CPU normalise in their own float order: a few ULPs apart.
                ASSERT_LT(glm::length(glm::vec3(n) - expectedN), 1e-5f) << x << "," << y << " sample " << k;
                glm::vec3 const expectedP =
                    desc.storesPosition ? glm::vec3(texel(rawPosition, x, y))
                                        : positionFromWindowDepth(invViewProj, {x, kH - 1 - y}, places[std::size_t(k)],
                                                                  kW, kH, rawDepth.at(x, y, 0));
                // Unprojecting in float on both sides: within 1e-5 of the eye distance (a sample's
                // place in the pixel moves it by about 1e-2 of it at this size).
                float const tolerance = 1e-5f * glm::length(expectedP - camera.position);
                ASSERT_LE(glm::length(glm::vec3(p) - expectedP), tolerance) << x << "," << y << " sample " << k;
            }
    }
    EXPECT_GT(drawn, kW * kH * kSamples / 2) << "the courtyard fills most of the frame";
    // Each sample is its own: where the layout rebuilds position, sample 3 lies elsewhere in the
    // pixel than sample 0 on every surface; classic stores the pixel's centre for every sample of a
    // surface, so they differ only at silhouettes.
    int differ = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) differ += texel(decoded[0][0], x, y) != texel(decoded[3][0], x, y);
    EXPECT_GT(differ, 0);
    if (desc.storesPosition)
        EXPECT_LT(differ, kW * kH / 4);
    else
        EXPECT_GT(differ, kW * kH / 2);

    FloatImage const counts = renderer.msaaDistinctSampleCounts(camera.position);
    FloatImage const mask = renderer.readAttachment(Attachment::ComplexPixels);
    ASSERT_EQ(counts.width, kW);
    ASSERT_EQ(counts.height, kH);
    ASSERT_EQ(counts.channels, 1);
    std::array<int, kSamples + 1> histogram{};
    int cpuMismatches = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            int const n = int(counts.at(x, y, 0));
            ASSERT_EQ(float(n), counts.at(x, y, 0));
            ASSERT_GE(n, 1);
            ASSERT_LE(n, kSamples);
            ++histogram[std::size_t(n)];
            // The same shader functions on the same samples: exactly the detection's verdict.
            ASSERT_EQ(n == 1, mask.at(x, y, 0) < 0.5f) << x << "," << y;
            std::array<MsaaSampleValues, kSamples> v;
            for (std::size_t k = 0; k < v.size(); ++k)
                v[k] = {texel(decoded[k][0], x, y), texel(decoded[k][1], x, y), texel(decoded[k][2], x, y)};
            cpuMismatches += msaaDistinctSamples(v, camera.position) != n;
        }
    // The CPU computes the eye distance and the dot products in its own float order, so a sample
    // just at a threshold may fall on either side: allow 0.2 % of the pixels (none seen on llvmpipe).
    EXPECT_LE(cpuMismatches, kW * kH / 500);
    int const complex = kW * kH - histogram[1];
    EXPECT_GT(complex, kW * kH / 100) << "silhouettes and the background edge are complex";
    EXPECT_LT(complex, kW * kH / 4) << "the courtyard's flat walls and floor are simple in every layout";
    EXPECT_GT(histogram[2], 0);
    ASSERT_TRUE(stats.complexPixelShare.has_value());
    EXPECT_DOUBLE_EQ(double(complex) / (kW * kH), *stats.complexPixelShare);
}

// Every layout in one case: a case's context and shaders cost more than a layout's checks.
TEST_F(MsaaViewsGlTest, DecodedSamplesAndCountsAreEachLayoutsOwn) {
    for (GBufferLayout layout :
         {GBufferLayout::Classic, GBufferLayout::Packed, GBufferLayout::Naive8, GBufferLayout::Rgb10a2}) {
        SCOPED_TRACE(std::string(layoutDesc(layout).name));
        checkLayout(*renderer_, camera_, lights_, layout);
    }
}

}  // namespace
