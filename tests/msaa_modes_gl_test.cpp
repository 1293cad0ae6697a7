// msaa (docs/msaa.md) beyond the quad pass and the classic layout, on the default scene at 160x90:
// the light volumes lit per sample equal the quad pass lit per sample with every inside-safe cull
// mode, edges in volumes mode equals per-sample within the quad test's bound, every layout has its
// multisampled G-buffer, and the modes that cannot (and a G-buffer over the memory budget) refuse in
// one sentence and fall back to msaa off, the frame unchanged.
#include "core/msaa.h"
#include "gl_fixture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace gbl;

namespace {

constexpr int kW = 160, kH = 90;
// Half an fp16 ulp, relative: the rounding of one store into the RGBA16F lit image.
constexpr double kHalfUlp = 1.0 / 2048.0;

struct Diff {
    double max = 0.0;
    double mean = 0.0;
    double maxComplex = 0.0;  // at the pixels the mask calls complex
    double maxSimple = 0.0;
    int over = 0;        // pixels beyond the bound
    int overSimple = 0;  // simple pixels beyond it
};

class MsaaModesGlTest : public test::CourtyardGlTest {
protected:
    MsaaModesGlTest() : CourtyardGlTest(kW, kH) {}

    static PipelineSettings settings(LightingMode mode, Msaa msaa, MsaaLighting lighting = MsaaLighting::PerSample,
                                     CullMode cull = CullMode::Front) {
        PipelineSettings s;
        s.lightCubes = false;  // the lighting alone
        s.mode = mode;
        s.cull = cull;
        s.msaa = msaa;
        s.msaaLighting = lighting;
        return s;
    }

    FloatImage lighting(PipelineSettings const& s) {
        FrameStats const st = renderer_->render({camera_, lights_, s, true});
        EXPECT_EQ(st.msaaUsed, s.msaa) << st.fallbackReason;
        EXPECT_EQ(st.modeUsed, s.mode) << st.fallbackReason;
        EXPECT_EQ(st.glErrors, 0u);
        return renderer_->readAttachment(Attachment::Lighting);
    }

    // a against b, each pixel's largest channel difference; `bound(value, complex)` the allowed one.
    template <class Bound>
    static Diff compare(FloatImage const& a, FloatImage const& b, FloatImage const& complex, Bound bound) {
        Diff d;
        double sum = 0.0;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                double m = 0.0;
                bool over = false;
                bool const isComplex = complex.at(x, y, 0) > 0.5f;
                for (int c = 0; c < 3; ++c) {
                    double const e = std::abs(double(a.at(x, y, c)) - b.at(x, y, c));
                    m = std::max(m, e);
                    over |= e > bound(std::abs(double(b.at(x, y, c))), isComplex);
                }
                d.over += over;
                d.overSimple += over && !isComplex;
                d.max = std::max(d.max, m);
                sum += m;
                double& side = isComplex ? d.maxComplex : d.maxSimple;
                side = std::max(side, m);
            }
        d.mean = sum / (kW * kH);
        return d;
    }
};

// The volumes add each light by fp16 blending, one rounding per light over the pixel, into each
// sample; the quad pass sums in fp32 and stores once. light_modes_gl_test bounds the difference by 16
// half-ulps of the value plus 1e-4 (the darkest lit values' fp16 spacing); the resolve's average of
// the samples rounds once more, one half-ulp. At a complex pixel each sample rounds at its own value,
// up to 4 times the average (one lit sample of 4): the bound of 4 times the value there.
double volumeBound(double v, bool complex) {
    return 17 * kHalfUlp * v * (complex ? 4.0 : 1.0) + 1e-4;
}
// The edges test's bound (msaa_gl_test): simple pixels' samples agree within the thresholds.
double edgesBound(double, bool) {
    return 0.02;
}

}  // namespace

TEST_F(MsaaModesGlTest, VolumesPerSampleEqualsQuadPerSampleWithEveryInsideSafeCullMode) {
    FloatImage const quad = lighting(settings(LightingMode::Quad, Msaa::X4));
    FloatImage const complex = renderer_->readAttachment(Attachment::ComplexPixels);
    FloatImage const volumesOff = lighting(settings(LightingMode::Volumes, Msaa::Off));
    // back is inside-safe here too: this camera stands outside every volume (light_modes_gl_test).
    for (CullMode cull : {CullMode::Back, CullMode::Front, CullMode::Flip, CullMode::Stencil}) {
        FloatImage const volumes = lighting(settings(LightingMode::Volumes, Msaa::X4, MsaaLighting::PerSample, cull));
        Diff const d = compare(volumes, quad, complex, volumeBound);
        // The samples were lit, not pixel centres: the silhouettes differ from the msaa off frame.
        Diff const off = compare(volumes, volumesOff, complex, edgesBound);
        std::printf(
            "volumes/%s per-sample vs quad per-sample: max %.3g (complex pixels %.3g), mean %.3g; vs msaa "
            "off: %d pixels beyond 0.02, max %.3g\n",
            enumName(kCullModeNames, cull).data(), d.max, d.maxComplex, d.mean, off.over, off.maxComplex);
        EXPECT_EQ(d.over, 0) << enumName(kCullModeNames, cull) << ": max " << d.max;
        EXPECT_GT(off.over, 10) << "antialiased edges";
        // A simple pixel's samples may lie on a triangle that misses the pixel centre (their
        // attributes are interpolated there, the msaa off pixel is another triangle's): rare.
        EXPECT_LT(off.overSimple, kW * kH / 100) << "simple pixels: a sample's surface is the pixel centre's";
    }
}

// msaa off in volumes mode (every cull mode's stencil masks as before: 0xFF) gives the same frame bit
// for bit before and after msaa volumes frames, whose stencil masks it must not inherit.
TEST_F(MsaaModesGlTest, VolumesMsaaOffFramesAreBitIdenticalWhateverRanBefore) {
    for (CullMode cull : {CullMode::Stencil, CullMode::Flip}) {
        PipelineSettings const off = settings(LightingMode::Volumes, Msaa::Off, MsaaLighting::Edges, cull);
        FloatImage const before = lighting(off);
        lighting(settings(LightingMode::Volumes, Msaa::X4, MsaaLighting::Edges, cull));
        lighting(settings(LightingMode::Volumes, Msaa::X2, MsaaLighting::PerSample, cull));
        EXPECT_EQ(lighting(off).pixels, before.pixels) << enumName(kCullModeNames, cull);
    }
}

// edges in volumes mode: the complex pixels lit sample by sample as per-sample lights them (the same
// draws, blends and order), the simple ones once at the centre: the bound of the quad pass's edges test.
TEST_F(MsaaModesGlTest, VolumesEdgesEqualsVolumesPerSampleWithinABound) {
    for (CullMode cull : {CullMode::Flip, CullMode::Stencil}) {
        FloatImage const perSample = lighting(settings(LightingMode::Volumes, Msaa::X4, MsaaLighting::PerSample, cull));
        FloatImage const edges = lighting(settings(LightingMode::Volumes, Msaa::X4, MsaaLighting::Edges, cull));
        FloatImage const complex = renderer_->readAttachment(Attachment::ComplexPixels);
        FloatImage const quadEdges = lighting(settings(LightingMode::Quad, Msaa::X4, MsaaLighting::Edges));
        Diff const d = compare(edges, perSample, complex, edgesBound);
        Diff const q = compare(edges, quadEdges, complex, volumeBound);
        std::printf(
            "volumes/%s edges vs per-sample: max %.3g, mean %.3g, complex pixels %.3g; vs quad edges: max "
            "%.3g\n",
            enumName(kCullModeNames, cull).data(), d.max, d.mean, d.maxComplex, q.max);
        EXPECT_LE(d.maxComplex, 1e-6) << "complex pixels are lit per sample by both";
        EXPECT_EQ(d.over, 0);
        EXPECT_LE(d.mean, 1e-3);
        EXPECT_EQ(q.over, 0) << "volumes edges is quad edges, blended: max " << q.max;
    }
}

// Every layout writes its multisampled G-buffer and decodes each sample: per-sample agrees with that
// layout's msaa off frame at simple pixels (their samples lie on one surface, within the thresholds:
// the 0.02 of the edges bound, but for under 1 % of pixels), differs at silhouettes, and edges lights
// its complex pixels as per-sample does and the others within the edges bound. The layouts that
// rebuild position unproject each sample's depth at its own place (GL_SAMPLE_POSITION) and a simple
// pixel's mean depth at the centre, so their complex share is classic's.
TEST_F(MsaaModesGlTest, EveryLayoutLightsItsSamples) {
    // Each layout lit by the quad pass; the volumes in packed, which test a multisampled copy of the
    // depth (the other two rebuilding layouts take the same path; classic: the tests above).
    std::vector<std::pair<GBufferLayout, LightingMode>> cases;
    for (std::size_t layout = 0; layout < kGBufferLayoutNames.size(); ++layout)
        cases.emplace_back(GBufferLayout(layout), LightingMode::Quad);
    cases.emplace_back(GBufferLayout::Packed, LightingMode::Volumes);
    for (auto const& [layout, mode] : cases) {
        auto const in = [&](Msaa msaa, MsaaLighting l) {
            PipelineSettings s = settings(mode, msaa, l, CullMode::Stencil);
            s.layout = layout;
            return s;
        };
        std::string const what =
            std::string(enumName(kGBufferLayoutNames, layout)) + "/" + std::string(enumName(kLightingModeNames, mode));
        FloatImage const off = lighting(in(Msaa::Off, MsaaLighting::PerSample));
        FloatImage const perSample = lighting(in(Msaa::X4, MsaaLighting::PerSample));
        FloatImage const edges = lighting(in(Msaa::X4, MsaaLighting::Edges));
        FloatImage const complex = renderer_->readAttachment(Attachment::ComplexPixels);
        Diff const d = compare(perSample, off, complex, edgesBound);
        Diff const e = compare(edges, perSample, complex, edgesBound);
        std::printf(
            "%s: per-sample vs off: %d simple pixels beyond 0.02, complex max %.3g; edges vs "
            "per-sample: complex %.3g, max %.3g; complex share %.3f\n",
            what.c_str(), d.overSimple, d.maxComplex, e.maxComplex, e.max, renderer_->complexPixelShare());
        EXPECT_LT(d.overSimple, kW * kH / 100) << what << ": as in the volumes test";
        EXPECT_GE(d.maxComplex, 0.1) << what << ": the silhouettes are antialiased";
        EXPECT_LE(e.maxComplex, 1e-6) << what;
        EXPECT_EQ(e.over, 0) << what;
        EXPECT_GT(renderer_->complexPixelShare(), 0.01) << what;
    }
}

// The modes that cannot light samples, split targets and a G-buffer over the memory budget: one
// sentence each, and the frame is the msaa off frame, bit for bit.
TEST_F(MsaaModesGlTest, ModesThatCannotAndTooLargeAGBufferRefuseInOneSentence) {
    struct Case {
        LightingMode mode;
        std::string sentence;
    };
    std::vector<Case> cases{{LightingMode::Forward,
                             "msaa 4 is lit by the quad and volumes passes only and this frame "
                             "ran forward mode, so msaa was off"},
                            {LightingMode::ForwardPlus,
                             "msaa 4 is lit by the quad and volumes passes only and this "
                             "frame ran forward+ mode, so msaa was off"}};
    if (caps().computeShaders)
        for (LightingMode m : {LightingMode::Tiled, LightingMode::Clustered})
            cases.push_back({m, "msaa 4 is lit by the quad and volumes passes only and this frame ran " +
                                    std::string(enumName(kLightingModeNames, m)) + " mode, so msaa was off"});
    else
        std::printf("tiled and clustered not checked: this context has no compute shaders\n");
    for (Case const& c : cases) {
        FrameStats const st = renderer_->render({camera_, lights_, settings(c.mode, Msaa::X4), true});
        EXPECT_EQ(st.modeUsed, c.mode);
        EXPECT_EQ(st.msaaUsed, Msaa::Off);
        EXPECT_EQ(st.fallbackReason, c.sentence);
        EXPECT_EQ(st.glErrors, 0u);
    }
    PipelineSettings split = settings(LightingMode::Volumes, Msaa::X2);
    split.accumulation = LightAccumulation::Split;
    FrameStats const sp = renderer_->render({camera_, lights_, split, true});
    EXPECT_EQ(sp.msaaUsed, Msaa::Off);
    EXPECT_EQ(sp.fallbackReason, "msaa 2 lights into one target, not split ones, so msaa was off");

    // A driver that reports 1000 KiB free: the budget is half, 512000 bytes. Classic at 4 samples
    // needs 36 bytes (its depth-stencil 8) x 4 x 160 x 90 = 2073600 bytes; volumes add their lit
    // image, 8 bytes x 4 a pixel.
    GlCaps small = caps();
    small.freeVideoMemoryKiB = 1000;
    small.freeVideoMemorySource = "GL_NVX_gpu_memory_info";
    Renderer limited(small, kW, kH);
    limited.setScene(scene_);
    for (LightingMode mode : {LightingMode::Quad, LightingMode::Volumes}) {
        FloatImage const want = lighting(settings(mode, Msaa::Off));
        FrameStats const st = limited.render({camera_, lights_, settings(mode, Msaa::X4), true});
        EXPECT_EQ(st.msaaUsed, Msaa::Off);
        // The volumes light into the single-sample lit image: the same targets as the quad pass.
        EXPECT_EQ(st.fallbackReason,
                  "msaa 4 needs 2 MB for its multisampled targets at 160x90 and the budget is 1 MB (half "
                  "the free video memory GL_NVX_gpu_memory_info reported), so msaa was off");
        EXPECT_EQ(limited.readAttachment(Attachment::Lighting).pixels, want.pixels) << "the msaa off frame";
        EXPECT_EQ(st.glErrors, 0u);
    }
    EXPECT_DOUBLE_EQ(msaaTargetBytes(layoutDesc(GBufferLayout::Classic), 4, kW, kH), 2073600.0);
    // packed: its 12 bytes a pixel (gbuffer_layout.h), 8 samples of each.
    EXPECT_DOUBLE_EQ(msaaTargetBytes(layoutDesc(GBufferLayout::Packed), 8, kW, kH), 12.0 * 8 * kW * kH);
    // The Stats window's and bench's line: bytes x samples x pixels, in tenths of a megabyte.
    EXPECT_EQ(msaaMemoryLine(layoutDesc(GBufferLayout::Classic), kW, kH),
              "msaa targets at 160x90: 2x 1.0 MB, 4x 2.1 MB, 8x 4.1 MB");
    // Without a report: the fixed budget of 1 GiB, which 8 samples of classic pass at 1920x1080
    // (597 MB) and fail at 7680x4320 (9.6 GB).
    EXPECT_FALSE(msaaBudgetRefusal(Msaa::X8, msaaTargetBytes(layoutDesc(GBufferLayout::Classic), 8, 1920, 1080),
                                   kMsaaFixedBudgetBytes, "fixed", 1920, 1080));
    EXPECT_EQ(msaaBudgetRefusal(Msaa::X8, msaaTargetBytes(layoutDesc(GBufferLayout::Classic), 8, 7680, 4320),
                                kMsaaFixedBudgetBytes, "fixed", 7680, 4320),
              "msaa 8 needs 9555 MB for its multisampled targets at 7680x4320 and the budget is 1074 MB (fixed), so "
              "msaa was off");
}
