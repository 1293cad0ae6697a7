// Light-by-light accumulation in every lighting mode: K = 0 is ambient alone, K = N the full frame,
// the sum grows with K, and lit(K) - lit(K-1) is the CPU evaluation of light K (docs/lighting.md).
#include "core/shading_cpu.h"
#include "gl_fixture.h"
#include "passes/wireframes.h"
#include "scene/default_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace gbl;
using gbl::test::GlTest;

namespace {

constexpr int kW = 240, kH = 135;

double rgbSum(FloatImage const& img) {
    double s = 0.0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            for (int c = 0; c < 3; ++c) s += img.at(x, y, c);
    return s;
}

double maxAbsDiff(FloatImage const& a, FloatImage const& b) {
    double m = 0.0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 3; ++c) m = std::max(m, double(std::abs(a.at(x, y, c) - b.at(x, y, c))));
    return m;
}

class AccumulateGlTest : public test::CourtyardGlTest {
protected:
    AccumulateGlTest() : CourtyardGlTest(kW, kH) {}
    void SetUp() override {
        CourtyardGlTest::SetUp();
        if (IsSkipped() || HasFatalFailure()) return;
        // The CPU reference reads the surface from a deferred G-buffer (forward mode has none).
        PipelineSettings quad = settings(LightingMode::Quad);
        lighting(quad, std::nullopt);
        position_ = renderer_->readAttachment(Attachment::Position);
        normal_ = renderer_->readAttachment(Attachment::Normal);
        albedo_ = renderer_->readAttachment(Attachment::AlbedoSpec);
    }

    static PipelineSettings settings(LightingMode mode) {
        PipelineSettings s;
        s.mode = mode;
        s.lightCubes = false;  // the lighting alone
        s.normalMaps = false;  // forward and deferred then see the same normals
        return s;
    }

    std::vector<LightingMode> modes() const {
        std::vector<LightingMode> m{LightingMode::Quad, LightingMode::Volumes, LightingMode::Forward};
        if (caps().computeShaders) m.push_back(LightingMode::Tiled);
        return m;
    }

    FloatImage lighting(PipelineSettings const& s, std::optional<int> k, bool contribution = false,
                        bool outline = false, Attachment read = Attachment::Lighting) {
        FrameInput in{camera_, lights_, s, true};
        in.accumulateLights = k;
        in.lightContribution = contribution;
        in.outlineAccumulated = outline;
        FrameStats const st = renderer_->render(in);
        EXPECT_EQ(st.modeUsed, s.mode) << st.fallbackReason;
        EXPECT_EQ(st.glErrors, 0u);
        return renderer_->readAttachment(read);
    }
    // The display image (the tonemapped lit image with the overlays drawn on it).
    FloatImage display(PipelineSettings const& s, std::optional<int> k, bool outline = false) {
        return lighting(s, k, false, outline, Attachment::Final);
    }

    // Light `index` alone on the CPU at every covered pixel, against `gpu` (a difference of two
    // lit images, or a contribution frame); returns the number of pixels over the bound.
    int pixelsOverCpu(FloatImage const& gpu, int index, LightingMode mode, double* maxErr) {
        int over = 0, covered = 0;
        for (int y = 0; y < kH; ++y) {
            for (int x = 0; x < kW; ++x) {
                if (position_.at(x, y, 3) <= 0.0f) continue;  // background
                ++covered;
                ShadingInputs in;
                in.position = {position_.at(x, y, 0), position_.at(x, y, 1), position_.at(x, y, 2)};
                in.normal = glm::normalize(glm::vec3(normal_.at(x, y, 0), normal_.at(x, y, 1), normal_.at(x, y, 2)));
                in.albedo = {albedo_.at(x, y, 0), albedo_.at(x, y, 1), albedo_.at(x, y, 2)};
                in.specular = albedo_.at(x, y, 3);
                in.viewPosition = camera_.position;
                in.shininess = settings(mode).shininess;
                glm::vec3 const expected = shadeLightCpu(lights_[std::size_t(index)], in).total();
                bool bad = false;
                for (int c = 0; c < 3; ++c) {
                    double const err = std::abs(double(gpu.at(x, y, c)) - expected[c]);
                    *maxErr = std::max(*maxErr, err);
                    // Deferred: two fp16 values (2^-11 relative each) and GPU-vs-CPU pow(), the
                    // 2e-3 relative bound of renderer_gl_test, twice. Forward shades the exact
                    // surface, not the stored one: the forward-vs-quad bound of light_modes_gl_test.
                    double const allowed = mode == LightingMode::Forward
                                               ? 0.03 * std::abs(expected[c]) + 2e-3
                                               : 4e-3 * std::max(1.0, double(std::abs(expected[c])));
                    bad = bad || err > allowed;
                }
                over += bad;
            }
        }
        EXPECT_GT(covered, kW * kH / 2) << "the camera should see mostly floor and walls";
        return over;
    }

    FloatImage position_, normal_, albedo_;
};

}  // namespace

TEST_F(AccumulateGlTest, ZeroLightsIsAmbientAloneAndAllLightsIsTheFullFrame) {
    for (LightingMode mode : modes()) {
        SCOPED_TRACE(std::string(enumName(kLightingModeNames, mode)));
        PipelineSettings const s = settings(mode);
        FloatImage const none = [&] {
            renderer_->render({camera_, {}, s, true});
            return renderer_->readAttachment(Attachment::Lighting);
        }();
        // The same passes over the same (empty / full) light list: bit-identical.
        EXPECT_EQ(maxAbsDiff(lighting(s, 0), none), 0.0);
        EXPECT_EQ(maxAbsDiff(lighting(s, int(lights_.size())), lighting(s, std::nullopt)), 0.0);
        // Out of range clamps to the list.
        EXPECT_EQ(maxAbsDiff(lighting(s, 1000), lighting(s, std::nullopt)), 0.0);
        // And the empty frame is ambient x albedo where there is a surface (0.03 x albedo <= 0.03).
        double const meanEmpty = rgbSum(none) / (3.0 * kW * kH);
        EXPECT_GT(meanEmpty, 1e-4);
        EXPECT_LT(meanEmpty, 0.03);
    }
}

TEST_F(AccumulateGlTest, SumGrowsWithEveryLight) {
    for (LightingMode mode : modes()) {
        SCOPED_TRACE(std::string(enumName(kLightingModeNames, mode)));
        double last = -1.0;
        int grew = 0;
        for (int k = 0; k <= int(lights_.size()); ++k) {
            double const sum = rgbSum(lighting(settings(mode), k));
            EXPECT_GE(sum, last) << "k = " << k;
            grew += sum > last;
            last = sum;
        }
        // Most lights of the default scene reach something this camera sees.
        EXPECT_GT(grew, int(lights_.size()) / 2);
    }
}

TEST_F(AccumulateGlTest, EachStepAddsTheCpuEvaluationOfThatLight) {
    for (LightingMode mode : modes()) {
        for (int k : {1, 2, 7, int(lights_.size())}) {
            SCOPED_TRACE(std::string(enumName(kLightingModeNames, mode)) + " k=" + std::to_string(k));
            FloatImage const before = lighting(settings(mode), k - 1);
            FloatImage step = lighting(settings(mode), k);
            for (std::size_t i = 0; i < step.pixels.size(); ++i) step.pixels[i] -= before.pixels[i];
            double maxErr = 0.0;
            int const over = pixelsOverCpu(step, k - 1, mode, &maxErr);
            // Forward: silhouettes where the stored surface and the exact one differ (as in
            // light_modes_gl_test, under 1 pixel in 200); deferred: none.
            EXPECT_LE(over, mode == LightingMode::Forward ? kW * kH / 200 : 0) << "max error " << maxErr;
            double contribErr = 0.0;
            int const contribOver = pixelsOverCpu(lighting(settings(mode), k, true), k - 1, mode, &contribErr);
            EXPECT_LE(contribOver, mode == LightingMode::Forward ? kW * kH / 200 : 0) << "max error " << contribErr;
        }
    }
}

TEST_F(AccumulateGlTest, TheKthVolumeIsOutlinedAndOnlyIt) {
    // The outline is an overlay: it is on the display image, not in the lit image (the next test).
    PipelineSettings s = settings(LightingMode::Quad);
    int const k = 3;
    auto changed = [](FloatImage const& a, FloatImage const& b) {
        int n = 0;
        for (std::size_t i = 0; i < a.pixels.size(); i += std::size_t(a.channels))
            n += std::abs(a.pixels[i] - b.pixels[i]) + std::abs(a.pixels[i + 1] - b.pixels[i + 1]) > 1e-3f;
        return n;
    };
    int const outline = changed(display(s, k, true), display(s, k));
    EXPECT_GT(outline, 20) << "light 3's sphere should draw lines";
    // Accumulating outlines light k only, even with every wireframe switched on.
    s.volumeWireframes = true;
    EXPECT_EQ(changed(display(s, k, true), display(settings(LightingMode::Quad), k)), outline);
    // Without accumulation: all 32 volumes, a tangle of many more lines...
    FloatImage const full = display(settings(LightingMode::Quad), std::nullopt);
    int const all = changed(display(s, std::nullopt), full);
    EXPECT_GT(all, 3 * outline);
    // ...or the selected light's alone: the same sphere as light k's outline.
    FrameInput in{camera_, lights_, s, true};
    in.wireframeLight = k - 1;
    renderer_->render(in);
    int const selected = changed(renderer_->readAttachment(Attachment::Final), full);
    EXPECT_GE(selected, outline * 8 / 10);
    EXPECT_LE(selected, outline * 12 / 10);
    // An index past the list draws none (not all of them).
    in.wireframeLight = 1000;
    renderer_->render(in);
    EXPECT_EQ(changed(renderer_->readAttachment(Attachment::Final), full), 0);
}

TEST_F(AccumulateGlTest, AccumulatingEveryLightWithOutlinesGivesTheFullFramesLitImage) {
    // Issue 24: the lit image is the light sum, whatever overlays are on. With the wireframes, the
    // light-by-light outline and the cubes drawn into it (the old wiring), stepping k = 1..N left light
    // N's outline and cube in lit(N) while the full frame held every light's wireframe: `render
    // --accumulate 16` of 16 lights differed from the full frame by 2.0 (the lines' HDR intensity)
    // on light 16's outline. Now both are the light sum: bit-identical, the same passes over the same
    // lights, and every step equals the same step without the outline.
    for (LightingMode mode : modes()) {
        SCOPED_TRACE(std::string(enumName(kLightingModeNames, mode)));
        PipelineSettings s = settings(mode);
        s.lightCubes = true;
        s.volumeWireframes = true;
        FloatImage const full = lighting(s, std::nullopt);
        PipelineSettings plain = settings(mode);  // no overlay at all
        EXPECT_EQ(maxAbsDiff(full, lighting(plain, std::nullopt)), 0.0) << "the full frame's lit image";
        FloatImage last;
        for (int k = 1; k <= int(lights_.size()); ++k) {
            last = lighting(s, k, false, true);
            // A few steps against the same step without outline, wireframes or cubes.
            if (k == 1 || k == 7 || k == int(lights_.size())) {
                EXPECT_EQ(maxAbsDiff(last, lighting(plain, k)), 0.0) << "k = " << k;
            }
        }
        EXPECT_EQ(maxAbsDiff(last, full), 0.0) << "lit(N), outline on, against the full frame";
        // The outline is still drawn: on the display image.
        EXPECT_GT(maxAbsDiff(display(plain, int(lights_.size()), true), display(plain, int(lights_.size()))), 0.1);
    }
}

TEST(VolumeInstanceSlot, FollowsThePartitionOfThePreparedInstances) {
    std::vector<PointLight> lights(4);
    for (int i = 0; i < 4; ++i) lights[std::size_t(i)].position = {float(i) * 100.0f, 0.0f, 0.0f};
    Camera cam;
    cam.position = lights[2].position;  // inside light 2's volume only
    lights[1].intensity = 0.0f;         // no volume at all
    EXPECT_EQ(volumeInstanceSlot(lights, 0, cam, 1.0f, 1.0f), 0);
    EXPECT_EQ(volumeInstanceSlot(lights, 1, cam, 1.0f, 1.0f), std::nullopt);
    EXPECT_EQ(volumeInstanceSlot(lights, 3, cam, 1.0f, 1.0f), 1);  // second outside one
    EXPECT_EQ(volumeInstanceSlot(lights, 2, cam, 1.0f, 1.0f), 2);  // after both outside ones
    EXPECT_EQ(volumeInstanceSlot(lights, 4, cam, 1.0f, 1.0f), std::nullopt);
}
