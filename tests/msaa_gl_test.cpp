// msaa (docs/msaa.md) on the default scene at 4 samples: per-sample lighting equals the CPU shading
// of each sample (read back from the multisampled G-buffer) averaged; edges equals per-sample within
// a stated bound; resolve-first differs from per-sample only at complex pixels, and there beyond a
// threshold; msaa off renders bit-identical frames whatever ran before; a refused sample count,
// or mode gives one sentence and the frame falls back to msaa off.
#include "core/msaa.h"
#include "core/shading_cpu.h"
#include "gl_fixture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace gbl;

namespace {

constexpr int kW = 160, kH = 90;

class MsaaGlTest : public test::CourtyardGlTest {
protected:
    MsaaGlTest() : CourtyardGlTest(kW, kH) {}

    static PipelineSettings settings(Msaa msaa, MsaaLighting lighting = MsaaLighting::PerSample) {
        PipelineSettings s;
        s.lightCubes = false;  // the lighting alone
        s.msaa = msaa;
        s.msaaLighting = lighting;
        return s;
    }

    FloatImage lighting(PipelineSettings const& s, Renderer* r = nullptr) {
        Renderer& renderer = r ? *r : *renderer_;
        FrameStats const st = renderer.render({camera_, lights_, s, true});
        EXPECT_EQ(st.msaaUsed, s.msaa) << st.fallbackReason;
        EXPECT_EQ(st.glErrors, 0u);
        return renderer.readAttachment(Attachment::Lighting);
    }

    static double maxRgbDiff(FloatImage const& a, FloatImage const& b, int x, int y) {
        double m = 0.0;
        for (int c = 0; c < 3; ++c) m = std::max(m, std::abs(double(a.at(x, y, c)) - b.at(x, y, c)));
        return m;
    }
};

TEST_F(MsaaGlTest, PerSampleEqualsTheCpuShadingOfEachSampleAveraged) {
    PipelineSettings const s = settings(Msaa::X4);
    FloatImage const lit = lighting(s);
    constexpr int n = 4;
    std::vector<FloatImage> pos, nrm, alb, emi;
    for (int k = 0; k < n; ++k) {
        pos.push_back(renderer_->readMsaaSample(GBufferSlot::Position, k));
        nrm.push_back(renderer_->readMsaaSample(GBufferSlot::Normal, k));
        alb.push_back(renderer_->readMsaaSample(GBufferSlot::AlbedoSpec, k));
        emi.push_back(renderer_->readMsaaSample(GBufferSlot::Emissive, k));
        ASSERT_EQ(pos.back().width, kW) << "sample " << k << " read back";
    }
    EXPECT_TRUE(renderer_->readMsaaSample(GBufferSlot::Position, n).pixels.empty()) << "a sample past the count";
    int over = 0, mixed = 0, differing = 0;
    double maxErr = 0.0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            glm::vec3 sum(0.0f);
            int drawn = 0;
            for (int k = 0; k < n; ++k) {
                if (pos[k].at(x, y, 3) == 0.0f) continue;  // background: lit black
                ++drawn;
                ShadingInputs in;
                in.position = {pos[k].at(x, y, 0), pos[k].at(x, y, 1), pos[k].at(x, y, 2)};
                in.normal = glm::normalize(glm::vec3(nrm[k].at(x, y, 0), nrm[k].at(x, y, 1), nrm[k].at(x, y, 2)));
                in.albedo = {alb[k].at(x, y, 0), alb[k].at(x, y, 1), alb[k].at(x, y, 2)};
                in.specular = alb[k].at(x, y, 3);
                in.emissive = {emi[k].at(x, y, 0), emi[k].at(x, y, 1), emi[k].at(x, y, 2)};
                in.occlusion = emi[k].at(x, y, 3);
                in.viewPosition = camera_.position;
                shadingOf(s, in);
                sum += shadePointCpu(lights_, in, s.ambient);
            }
            mixed += drawn > 0 && drawn < n;
            for (int k = 1; k < n; ++k) {
                bool differ = false;
                for (int c = 0; c < 4; ++c) {
                    differ |= pos[k].at(x, y, c) != pos[0].at(x, y, c);
                    differ |= nrm[k].at(x, y, c) != nrm[0].at(x, y, c);
                    differ |= alb[k].at(x, y, c) != alb[0].at(x, y, c);
                }
                differing += differ;
            }
            glm::vec3 const expected = sum / float(n);
            bool bad = false;
            for (int c = 0; c < 3; ++c) {
                // The bound of gbuffer_layouts_gl_test (RGBA16F storage, pow() on the GPU), per sample.
                double const e = std::abs(double(lit.at(x, y, c)) - expected[c]);
                maxErr = std::max(maxErr, e);
                bad |= e > 8e-3 * std::abs(expected[c]) + 1e-3;
            }
            over += bad;
        }
    std::printf("per-sample vs CPU: max error %.3g; %d pixels partly covered, %d samples differ from sample 0\n",
                maxErr, mixed, differing);
    EXPECT_EQ(over, 0) << "max error " << maxErr;
    EXPECT_GT(differing, kW * kH / 20) << "the courtyard's edges: samples of one pixel on different surfaces";
}

// Edges lights simple pixels from sample 0, where per-sample averages samples that differ by less
// than the thresholds of core/msaa.h: the two agree within 0.02 at every pixel and 1e-3 on average.
TEST_F(MsaaGlTest, EdgesEqualsPerSampleWithinABound) {
    FloatImage const perSample = lighting(settings(Msaa::X4, MsaaLighting::PerSample));
    FloatImage const edges = lighting(settings(Msaa::X4, MsaaLighting::Edges));
    double const share = renderer_->complexPixelShare();
    FrameStats const st = renderer_->render({camera_, lights_, settings(Msaa::X4, MsaaLighting::Edges), true});
    ASSERT_TRUE(st.complexPixelShare) << "counted by the msaa_edges pass";
    EXPECT_NEAR(*st.complexPixelShare, share, 1e-9) << "the pass's count is the mask's share";
    FloatImage const complex = renderer_->readAttachment(Attachment::ComplexPixels);
    double maxDiff = 0.0, sum = 0.0, maxComplex = 0.0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            double const d = maxRgbDiff(perSample, edges, x, y);
            maxDiff = std::max(maxDiff, d);
            sum += d;
            if (complex.at(x, y, 0) > 0.5f) maxComplex = std::max(maxComplex, d);
        }
    double const mean = sum / (kW * kH);
    std::printf("edges vs per-sample: max %.3g, mean %.3g, at complex pixels max %.3g; complex share %.4f\n", maxDiff,
                mean, maxComplex, share);
    EXPECT_GT(share, 0.0);
    EXPECT_LT(share, 0.5);
    EXPECT_LE(maxComplex, 1e-6) << "complex pixels are lit per sample by both";
    EXPECT_LE(maxDiff, 0.02);
    EXPECT_LE(mean, 1e-3);
}

// Simple pixels: their samples agree within the thresholds, so averaging first changes little (the
// bound of the edges test). Complex pixels: normals and positions of two surfaces averaged, the
// halo, five times that and more (0.21 measured here).
TEST_F(MsaaGlTest, ResolveFirstDiffersFromPerSampleOnlyAtComplexPixels) {
    FloatImage const perSample = lighting(settings(Msaa::X4, MsaaLighting::PerSample));
    FloatImage const complex = renderer_->readAttachment(Attachment::ComplexPixels);
    FloatImage const resolved = lighting(settings(Msaa::X4, MsaaLighting::ResolveFirst));
    int complexCount = 0, haloed = 0;
    double maxSimple = 0.0, maxComplex = 0.0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            double const d = maxRgbDiff(perSample, resolved, x, y);
            if (complex.at(x, y, 0) > 0.5f) {
                ++complexCount;
                haloed += d > 0.02;
                maxComplex = std::max(maxComplex, d);
            } else {
                maxSimple = std::max(maxSimple, d);
            }
        }
    std::printf("resolve-first vs per-sample: simple pixels max %.3g; complex max %.3g, %d of %d beyond 0.02\n",
                maxSimple, maxComplex, haloed, complexCount);
    EXPECT_LE(maxSimple, 0.02);
    EXPECT_GT(complexCount, 0);
    EXPECT_GE(maxComplex, 5 * 0.02) << "the silhouettes halo where attributes were averaged";
    EXPECT_GT(haloed, complexCount / 50) << "beyond the simple pixels' bound at some of the complex ones";
}

TEST_F(MsaaGlTest, MsaaOffFramesAreBitIdenticalWhateverRanBefore) {
    PipelineSettings const off = settings(Msaa::Off);
    EXPECT_EQ(renderer_->framePasses({camera_, lights_, off}), framePasses(off, false));
    for (PassDecl const& p : renderer_->framePasses({camera_, lights_, off}))
        for (Resource r : p.samples) EXPECT_TRUE(r != Resource::MsaaPosition && r != Resource::MsaaDepth) << p.name();
    renderer_->render({camera_, lights_, off, true});
    FloatImage const lit0 = renderer_->readAttachment(Attachment::Lighting);
    FloatImage const final0 = renderer_->readAttachment(Attachment::Final);
    for (MsaaLighting l : {MsaaLighting::ResolveFirst, MsaaLighting::PerSample, MsaaLighting::Edges})
        lighting(settings(Msaa::X4, l));
    FloatImage const lit1 = lighting(off);
    FloatImage const final1 = renderer_->readAttachment(Attachment::Final);
    EXPECT_EQ(lit1.pixels, lit0.pixels);
    EXPECT_EQ(final1.pixels, final0.pixels);
}

TEST_F(MsaaGlTest, ARefusedSampleCountOrModeIsOneSentenceAndFallsBack) {
    PipelineSettings const off = settings(Msaa::Off);
    FloatImage const want = lighting(off);
    // A driver that offers 2 samples at most: 4 are refused with the limits it reported.
    GlCaps two = caps();
    two.maxColorTextureSamples = 2;
    std::unique_ptr<Renderer> limited = std::make_unique<Renderer>(two, kW, kH);
    limited->setScene(scene_);
    FrameStats const st = limited->render({camera_, lights_, settings(Msaa::X4), true});
    EXPECT_EQ(st.msaaUsed, Msaa::Off);
    EXPECT_EQ(st.fallbackReason, "4 samples exceed this driver's limit (GL_MAX_SAMPLES " +
                                     std::to_string(two.maxSamples) + ", GL_MAX_COLOR_TEXTURE_SAMPLES 2, " +
                                     "GL_MAX_DEPTH_TEXTURE_SAMPLES " + std::to_string(two.maxDepthTextureSamples) +
                                     "), so msaa was off");
    EXPECT_EQ(limited->readAttachment(Attachment::Lighting).pixels, want.pixels) << "the msaa off frame";
    FrameStats const ok = limited->render({camera_, lights_, settings(Msaa::X2), true});
    EXPECT_EQ(ok.msaaUsed, Msaa::X2) << ok.fallbackReason;

    // Volumes mode and the other layouts light their samples (msaa_modes_gl_test); forward does not.
    PipelineSettings forward = settings(Msaa::X4);
    forward.mode = LightingMode::Forward;
    FrameStats const v = renderer_->render({camera_, lights_, forward, true});
    EXPECT_EQ(v.msaaUsed, Msaa::Off);
    EXPECT_EQ(v.fallbackReason,
              "msaa 4 is lit by the quad and volumes passes only and this frame ran forward mode, so msaa was off");
    PipelineSettings packed = settings(Msaa::X4);
    packed.layout = GBufferLayout::Packed;
    packed.mode = LightingMode::Volumes;
    FrameStats const p = renderer_->render({camera_, lights_, packed, true});
    EXPECT_EQ(p.msaaUsed, Msaa::X4) << p.fallbackReason;
    EXPECT_EQ(p.fallbackReason, "");
    for (FrameStats const* f : {&st, &v, &p}) {
        EXPECT_EQ(std::count(f->fallbackReason.begin(), f->fallbackReason.end(), '.'), 0) << "one sentence";
        EXPECT_EQ(f->glErrors, 0u);
    }
}

}  // namespace
