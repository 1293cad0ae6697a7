// `accumulation: split` on the default scene: every deferred mode writes diffuse and specular light
// into two targets that match the CPU sums, the combine pass gives the single-target image, forward
// refuses with its reason, and the targets are viewable and exported.
#include "core/gbuffer_layout.h"
#include "core/shading_cpu.h"
#include "frame_export.h"
#include "gl_fixture.h"
#include "image/image_io.h"
#include "run_command.h"
#include "scene/default_scene.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace gbl;
using gbl::test::GlTest;

namespace {

constexpr int kW = 240, kH = 135;

class AccumulationSplitGlTest : public test::CourtyardGlTest {
protected:
    AccumulationSplitGlTest() : CourtyardGlTest(kW, kH) {}

    static PipelineSettings settings(LightingMode mode, LightAccumulation accumulation,
                                     GBufferLayout layout = GBufferLayout::Classic) {
        PipelineSettings s;
        s.mode = mode;
        s.accumulation = accumulation;
        s.layout = layout;
        s.lightCubes = false;  // the lighting alone
        return s;
    }

    FrameStats render(PipelineSettings const& s) {
        FrameStats const st = renderer_->render({camera_, lights_, s, true});
        EXPECT_EQ(st.modeUsed, s.mode) << st.fallbackReason;
        EXPECT_EQ(st.glErrors, 0u);
        return st;
    }

    std::vector<LightingMode> deferredModes() const {
        std::vector<LightingMode> m{LightingMode::Quad, LightingMode::Volumes};
        if (caps().computeShaders) m.insert(m.end(), {LightingMode::Tiled, LightingMode::Clustered});
        return m;
    }
};

std::string name(LightingMode mode) {
    return std::string(enumName(kLightingModeNames, mode));
}

}  // namespace

TEST_F(AccumulationSplitGlTest, EveryDeferredModeGivesTheSingleTargetImage) {
    for (GBufferLayout layout : {GBufferLayout::Classic, GBufferLayout::Packed})
        for (LightingMode mode : deferredModes()) {
            render(settings(mode, LightAccumulation::Single, layout));
            FloatImage const single = renderer_->readAttachment(Attachment::Lighting);
            FrameStats const st = render(settings(mode, LightAccumulation::Split, layout));
            EXPECT_EQ(st.accumulationUsed, LightAccumulation::Split) << name(mode);
            FloatImage const split = renderer_->readAttachment(Attachment::Lighting);
            // Single rounds the lit value to fp16 once; split rounds the diffuse and the specular sums
            // first (2^-11 relative each, weighted by albedo <= 1) and then the lit value: about
            // 3 x 2^-11 = 1.5e-3 of the value, 2e-3 with pow() ordering slack. Volumes blend every
            // light into fp16 targets in both cases, each rounding differently: the 8e-3 of
            // gbuffer_layouts_gl_test. 1e-4 absolute covers fp16's spacing near zero.
            double const relative = mode == LightingMode::Volumes ? 8e-3 : 2e-3;
            int over = 0, covered = 0;
            double maxErr = 0.0;
            for (int y = 0; y < kH; ++y)
                for (int x = 0; x < kW; ++x) {
                    covered += single.at(x, y, 3) > 0.0f;
                    for (int c = 0; c < 4; ++c) {
                        double const e = std::abs(double(split.at(x, y, c)) - single.at(x, y, c));
                        maxErr = std::max(maxErr, e);
                        over += e > relative * std::abs(single.at(x, y, c)) + 1e-4;
                    }
                }
            EXPECT_GT(covered, kW * kH / 2) << name(mode);
            EXPECT_EQ(over, 0) << layoutDesc(layout).name << "/" << name(mode) << ": max difference " << maxErr;
        }
}

TEST_F(AccumulationSplitGlTest, TheTwoTargetsHoldTheCpuSumsOfDiffuseAndSpecularLight) {
    for (LightingMode mode : deferredModes()) {
        PipelineSettings const s = settings(mode, LightAccumulation::Split);
        render(s);
        FloatImage const diffuse = renderer_->readAttachment(Attachment::DiffuseLight);
        FloatImage const specular = renderer_->readAttachment(Attachment::SpecularLight);
        FloatImage const pos = renderer_->readAttachment(Attachment::Position);
        FloatImage const nrm = renderer_->readAttachment(Attachment::Normal);
        FloatImage const alb = renderer_->readAttachment(Attachment::AlbedoSpec);
        int over = 0, lit = 0;
        double maxErr = 0.0;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                if (pos.at(x, y, 3) == 0.0f) continue;
                ShadingInputs in;
                in.position = {pos.at(x, y, 0), pos.at(x, y, 1), pos.at(x, y, 2)};
                in.normal = {nrm.at(x, y, 0), nrm.at(x, y, 1), nrm.at(x, y, 2)};
                in.albedo = glm::vec3(1.0f);  // diffuse light: N.L * attenuation * colour, no albedo
                in.specular = alb.at(x, y, 3);
                in.viewPosition = camera_.position;
                in.shininess = s.shininess;
                glm::vec3 d(0.0f), sp(0.0f);
                for (PointLight const& l : lights_) {
                    LightContribution const c = shadeLightCpu(l, in);
                    d += c.diffuse;
                    sp += c.specular;
                }
                lit += d.r + d.g + d.b > 0.0f;
                for (int c = 0; c < 3; ++c)
                    for (auto [got, want] :
                         {std::pair{diffuse.at(x, y, c), d[c]}, std::pair{specular.at(x, y, c), sp[c]}}) {
                        // The bound of gbuffer_layouts_gl_test: fp16 storage and blending, pow() on the GPU.
                        double const e = std::abs(double(got) - want);
                        maxErr = std::max(maxErr, e);
                        over += e > 8e-3 * std::abs(want) + 1e-3;
                    }
            }
        EXPECT_GT(lit, kW * kH / 10) << name(mode) << ": the lights reach the floor";
        EXPECT_EQ(over, 0) << name(mode) << ": max error " << maxErr;
    }
}

TEST_F(AccumulationSplitGlTest, ForwardRefusesSplitAndSaysWhy) {
    FrameStats const st = render(settings(LightingMode::Forward, LightAccumulation::Split));
    EXPECT_EQ(st.accumulationUsed, LightAccumulation::Single);
    EXPECT_NE(st.fallbackReason.find("forward"), std::string::npos) << st.fallbackReason;
    // The image is forward's own single-target one.
    FloatImage const split = renderer_->readAttachment(Attachment::Lighting);
    render(settings(LightingMode::Forward, LightAccumulation::Single));
    EXPECT_EQ(split.pixels, renderer_->readAttachment(Attachment::Lighting).pixels);
}

TEST_F(AccumulationSplitGlTest, TargetsAreViewableAndExported) {
    PipelineSettings const s = settings(LightingMode::Quad, LightAccumulation::Split);
    FrameStats const stats = render(s);
    std::string const dir = test::freshTempDir("accumulation_split_export");
    FrameExport frame{
        camera_, lights_, s, stats, scene_.triangleCount(), {DebugView::DiffuseLight, DebugView::SpecularLight}};
    ASSERT_FALSE(exportFrame(*renderer_, frame, dir));
    for (char const* f :
         {"diffuse_light.exr", "specular_light.exr", "view_diffuse_light.png", "view_specular_light.png"})
        EXPECT_TRUE(std::filesystem::exists(dir + "/" + f)) << f;
    auto const exported = readImage(dir + "/diffuse_light.exr");
    ASSERT_TRUE(exported);
    EXPECT_EQ(exported->pixels, renderer_->readAttachment(Attachment::DiffuseLight).pixels);
    // The view shows the stored value remapped over [0, 1]: a pixel's red within two 8-bit steps.
    ViewTarget t;
    ViewParams p;
    p.view = DebugView::SpecularLight;
    p.channelMask = 1;
    renderer_->drawView(p, {camera_, lights_, s}, t);
    FloatImage const view = renderer_->readViewTarget(t);
    FloatImage const stored = renderer_->readAttachment(Attachment::SpecularLight);
    int checked = 0;
    for (int y = 0; y < kH; y += 7)
        for (int x = 0; x < kW; x += 7) {
            float const v = std::clamp(stored.at(x, y, 0), 0.0f, 1.0f);
            EXPECT_NEAR(view.at(x, y, 0), v, 2.0f / 255.0f) << x << ", " << y;
            ++checked;
        }
    EXPECT_GT(checked, 100);
    // A single-target frame writes no accumulation files.
    FrameStats const single = render(settings(LightingMode::Quad, LightAccumulation::Single));
    std::string const dir2 = test::freshTempDir("accumulation_single_export");
    ASSERT_FALSE(exportFrame(*renderer_, {camera_, lights_, s, single, scene_.triangleCount(), {}}, dir2));
    EXPECT_FALSE(std::filesystem::exists(dir2 + "/diffuse_light.exr"));
}
