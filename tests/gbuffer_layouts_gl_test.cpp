// The G-buffer layouts on the default scene: each mode's lighting against the CPU equation on that
// layout's own decoded inputs, packed against classic, naive8's visible highlight error, live
// switching, the decoded viewers and the export of raw attachments.
#include "core/gbuffer_layout.h"
#include "core/shading_cpu.h"
#include "frame_export.h"
#include "gl_fixture.h"
#include "image/image_io.h"
#include "renderer_test_access.h"
#include "run_command.h"
#include "scene/default_scene.h"
#include "test_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

using namespace gbl;
using gbl::test::GlTest;

namespace {

constexpr int kW = 320, kH = 180;
constexpr std::array<GBufferLayout, 4> kAllLayouts{GBufferLayout::Classic, GBufferLayout::Packed, GBufferLayout::Naive8,
                                                   GBufferLayout::Rgb10a2};

struct Diff {
    double maxAbs = 0.0;
    double meanAbs = 0.0;
    double p99 = 0.0;  // 99th percentile of the per-pixel max channel error
};

Diff compareRgb(FloatImage const& a, FloatImage const& b) {
    Diff d;
    std::vector<double> perPixel;
    double sum = 0.0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            double m = 0.0;
            for (int c = 0; c < 3; ++c) {
                double const e = std::abs(double(a.at(x, y, c)) - b.at(x, y, c));
                sum += e;
                m = std::max(m, e);
            }
            perPixel.push_back(m);
            d.maxAbs = std::max(d.maxAbs, m);
        }
    d.meanAbs = sum / (double(a.width) * a.height * 3);
    std::sort(perPixel.begin(), perPixel.end());
    d.p99 = perPixel[perPixel.size() * 99 / 100];
    return d;
}

class GBufferLayoutsGlTest : public test::CourtyardGlTest {
protected:
    GBufferLayoutsGlTest() : CourtyardGlTest(kW, kH) {}

    static PipelineSettings settings(GBufferLayout layout, LightingMode mode = LightingMode::Quad) {
        PipelineSettings s;
        s.layout = layout;
        s.mode = mode;
        s.lightCubes = false;  // the lighting alone
        s.normalMaps = false;  // smooth surfaces: the normal's encoding is what differs, not the texture
        return s;
    }

    FloatImage lighting(PipelineSettings const& s) {
        FrameStats const st = renderer_->render({camera_, lights_, s, true});
        EXPECT_EQ(st.modeUsed, s.mode) << st.fallbackReason;
        EXPECT_EQ(st.layout, s.layout);
        EXPECT_EQ(st.glErrors, 0u);
        return renderer_->readAttachment(Attachment::Lighting);
    }
};

}  // namespace

TEST_F(GBufferLayoutsGlTest, EveryDeferredModeMatchesTheCpuOnTheLayoutsOwnInputs) {
    std::vector<LightingMode> modes{LightingMode::Quad, LightingMode::Volumes};
    // Tiled and clustered (GL 4.3 compute) read the G-buffer through the same decode.
    if (caps().computeShaders) modes.insert(modes.end(), {LightingMode::Tiled, LightingMode::Clustered});
    for (GBufferLayout layout : kAllLayouts) {
        for (LightingMode mode : modes) {
            PipelineSettings const s = settings(layout, mode);
            FloatImage const lit = lighting(s);
            // What export writes as position.exr / normal.exr / albedo.png: the decoded inputs.
            FloatImage const pos = renderer_->readAttachment(Attachment::Position);
            FloatImage const nrm = renderer_->readAttachment(Attachment::Normal);
            FloatImage const alb = renderer_->readAttachment(Attachment::AlbedoSpec);
            int covered = 0, over = 0;
            double maxErr = 0.0;
            for (int y = 0; y < kH; ++y)
                for (int x = 0; x < kW; ++x) {
                    if (pos.at(x, y, 3) == 0.0f) continue;
                    ++covered;
                    ShadingInputs in;
                    in.position = {pos.at(x, y, 0), pos.at(x, y, 1), pos.at(x, y, 2)};
                    in.normal = {nrm.at(x, y, 0), nrm.at(x, y, 1), nrm.at(x, y, 2)};
                    in.albedo = {alb.at(x, y, 0), alb.at(x, y, 1), alb.at(x, y, 2)};
                    in.specular = alb.at(x, y, 3);
                    in.viewPosition = camera_.position;
                    in.shininess = s.shininess;
                    glm::vec3 const expected = shadePointCpu(lights_, in, s.ambient);
                    bool bad = false;
                    for (int c = 0; c < 3; ++c) {
                        // RGBA16F keeps 11 significant bits (2^-11 relative) and the volumes' additive
                        // blend rounds once per overlapping light (up to 16 here): 16 x 2^-11 ~ 8e-3
                        // relative, plus 1e-3 absolute for pow() differing between GPU and CPU.
                        double const e = std::abs(double(lit.at(x, y, c)) - expected[c]);
                        maxErr = std::max(maxErr, e);
                        bad |= e > 8e-3 * std::abs(expected[c]) + 1e-3;
                    }
                    over += bad;
                }
            std::string const what =
                std::string(layoutDesc(layout).name) + "/" + std::string(enumName(kLightingModeNames, mode));
            EXPECT_GT(covered, kW * kH / 2) << what;
            EXPECT_EQ(over, 0) << what << ": max error " << maxErr;
        }
    }
}

TEST_F(GBufferLayoutsGlTest, PackedStaysCloseToClassicOnTheDefaultScene) {
    FloatImage const classic = lighting(settings(GBufferLayout::Classic));
    Diff const packed = compareRgb(lighting(settings(GBufferLayout::Packed)), classic);
    Diff const ten = compareRgb(lighting(settings(GBufferLayout::Rgb10a2)), classic);
    Diff const naive = compareRgb(lighting(settings(GBufferLayout::Naive8)), classic);
    std::printf(
        "vs classic: packed max %.4g p99 %.4g mean %.3g | rgb10a2 max %.4g p99 %.4g mean %.3g | naive8 max "
        "%.4g p99 %.4g mean %.3g\n",
        packed.maxAbs, packed.p99, packed.meanAbs, ten.maxAbs, ten.p99, ten.meanAbs, naive.maxAbs, naive.p99,
        naive.meanAbs);
    // Packed differs from classic by classic's own rounding more than by packing: classic keeps
    // position in RGBA16F (a step of 2^-7 ~ 0.008 units at 8..16 units from the origin), packed
    // rebuilds it from 24-bit depth (sub-millimetre here) and decodes a 16-bit octahedral normal
    // (< 0.01 degrees). A position step of 0.008 units near a light of radius ~3..7 changes its
    // attenuation and (N.H)^32 by well under 1 %; with lit values up to ~1 here that is < 0.02 at
    // any pixel, and the rounding is rare enough that 99 % of pixels stay within 0.002 (about two
    // fp16 steps at 1). Measured on llvmpipe: max 0.0067, 99th percentile 0.00037.
    EXPECT_LT(packed.maxAbs, 0.02);
    EXPECT_LT(packed.p99, 0.002);
    // 10-bit normals round less than 8-bit ones.
    EXPECT_LT(ten.p99, naive.p99);
}

TEST_F(GBufferLayoutsGlTest, Naive8ShowsInASharpHighlight) {
    // One bright light over the smooth test floor, its highlight in view. 8-bit biased normals
    // store (0, 1, 0) as 128/255 per component: a 0.3 degree tilt (and 0.45 degree steps on curved
    // surfaces), which at shininess 128 shifts the narrow highlight enough to change the screen by
    // two 8-bit levels over a patch of pixels (92 on llvmpipe); packed's 0.01 degrees change no
    // pixel by more than one level (tonemap rounding).
    ASSERT_FALSE(renderer_->setScene(test::floorScene()));
    PointLight light;
    light.position = {0.0f, 1.0f, 0.0f};
    light.color = glm::vec3(1.0f);
    light.intensity = 4.0f;
    lights_ = {light};
    camera_.position = {0.0f, 1.2f, 3.0f};
    camera_.lookAt({0.0f, 0.0f, 0.0f});
    auto sharp = [&](GBufferLayout layout) {
        PipelineSettings s = settings(layout);
        s.shininess = 128.0f;
        return lighting(s);
    };
    // Visible = the tonemapped 8-bit image on screen changes by two levels or more.
    auto screenLevels = [&](GBufferLayout layout, FloatImage const& reference, int* pixels) {
        FloatImage const img = (sharp(layout), renderer_->readAttachment(Attachment::Final));
        int worst = 0;
        *pixels = 0;
        for (std::size_t i = 0; i < img.pixels.size(); i += 4) {
            int m = 0;
            for (int c = 0; c < 3; ++c)
                m = std::max(m, int(std::lround(std::abs(img.pixels[i + c] - reference.pixels[i + c]) * 255.0f)));
            worst = std::max(worst, m);
            *pixels += m >= 2;
        }
        return worst;
    };
    FloatImage const classicLit = sharp(GBufferLayout::Classic);
    FloatImage const classic = renderer_->readAttachment(Attachment::Final);
    Diff const packedHdr = compareRgb(sharp(GBufferLayout::Packed), classicLit);
    Diff const naiveHdr = compareRgb(sharp(GBufferLayout::Naive8), classicLit);
    int packedPixels = 0, naivePixels = 0;
    int const packedLevels = screenLevels(GBufferLayout::Packed, classic, &packedPixels);
    int const naiveLevels = screenLevels(GBufferLayout::Naive8, classic, &naivePixels);
    std::printf(
        "sharp highlight vs classic: packed HDR max %.4g, %d levels, %d pixels | naive8 HDR max %.4g, %d "
        "levels, %d pixels\n",
        packedHdr.maxAbs, packedLevels, packedPixels, naiveHdr.maxAbs, naiveLevels, naivePixels);
    EXPECT_LE(packedLevels, 1) << "packed must look the same as classic";
    EXPECT_GT(naivePixels, 20) << "the lesson's error must be visible somewhere";
    EXPECT_GT(naiveHdr.maxAbs, 4.0 * packedHdr.maxAbs);
}

TEST_F(GBufferLayoutsGlTest, SwitchingLayoutsLiveAndBackGivesTheSameFrame) {
    FloatImage const first = lighting(settings(GBufferLayout::Classic));
    FloatImage const packed = lighting(settings(GBufferLayout::Packed));
    EXPECT_EQ(renderer_->layout(), GBufferLayout::Packed);
    EXPECT_NE(first.pixels, packed.pixels) << "a different layout rounds differently somewhere";
    renderer_->resizeTargets(kW, kH);  // a resize keeps the layout
    EXPECT_EQ(renderer_->layout(), GBufferLayout::Packed);
    FloatImage const again = lighting(settings(GBufferLayout::Classic));
    EXPECT_EQ(first.pixels, again.pixels);
    // Both layouts' programs are kept: switching back and forth (what the A/B split does every
    // frame when its sides differ in layout) builds nothing more and gives the same frames.
    std::size_t const builds = RendererTestAccess::shaderBuilds(*renderer_);
    EXPECT_EQ(lighting(settings(GBufferLayout::Packed)).pixels, packed.pixels);
    EXPECT_EQ(lighting(settings(GBufferLayout::Classic)).pixels, first.pixels);
    EXPECT_EQ(RendererTestAccess::shaderBuilds(*renderer_), builds);
    EXPECT_GT(builds, 0u);
}

TEST_F(GBufferLayoutsGlTest, InspectorAndViewersShowDecodedValues) {
    for (GBufferLayout layout : kAllLayouts) {
        lighting(settings(layout));
        FloatImage const pos = renderer_->readAttachment(Attachment::Position);
        FloatImage const nrm = renderer_->readAttachment(Attachment::Normal);
        // The floor at the image's bottom centre faces +Y in every layout.
        int const x = kW / 2, y = kH - 4;
        PixelSample const px = renderer_->samplePixel(x, y, camera_);
        ASSERT_TRUE(px.covered) << layoutDesc(layout).name;
        EXPECT_NEAR(px.normal.y, 1.0f, 1e-3f) << layoutDesc(layout).name;
        EXPECT_NEAR(glm::length(glm::vec3(px.normal)), 1.0f, 1e-4f);
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(px.position[c], pos.at(x, y, c)) << "the inspector reads what export writes";
            EXPECT_EQ(px.normal[c], nrm.at(x, y, c));
        }
        // Position rebuilt from depth equals the one the inspector computes on the CPU.
        EXPECT_LT(glm::distance(glm::vec3(px.position), px.reconstructedPosition), 0.02f) << layoutDesc(layout).name;
    }
    // The normal viewer shows the decoded normal: within one 8-bit step across layouts.
    auto normalView = [&](GBufferLayout layout) {
        lighting(settings(layout));
        ViewTarget t;
        ViewParams p;
        p.view = DebugView::Normal;
        renderer_->drawView(p, {camera_, lights_, settings(layout)}, t);
        return renderer_->readViewTarget(t);
    };
    FloatImage const classicView = normalView(GBufferLayout::Classic);
    EXPECT_LE(compareRgb(normalView(GBufferLayout::Packed), classicView).maxAbs, 1.5 / 255.0);
}

TEST_F(GBufferLayoutsGlTest, RawViewsAndExportShowTheStoredAttachments) {
    PipelineSettings const s = settings(GBufferLayout::Packed);
    FrameStats const stats = renderer_->render({camera_, lights_, s, true});
    FloatImage const raw0 = renderer_->readRawAttachment(0);
    ASSERT_EQ(raw0.channels, 2);  // RG16: the octahedral normal
    EXPECT_TRUE(renderer_->readRawAttachment(3).pixels.empty()) << "packed has three attachments";
    // The floor's normal (0, 1, 0) encodes to oct (0, 1), stored biased as (0.5, 1).
    EXPECT_NEAR(raw0.at(kW / 2, kH - 4, 0), 0.5f, 1e-4f);
    EXPECT_NEAR(raw0.at(kW / 2, kH - 4, 1), 1.0f, 1e-4f);
    ViewTarget t;
    ViewParams p;
    p.view = DebugView::Raw0;
    p.channelMask = 1;  // the red channel alone, as grey
    renderer_->drawView(p, {camera_, lights_, s}, t);
    FloatImage const view = renderer_->readViewTarget(t);
    EXPECT_NEAR(view.at(kW / 2, kH - 4, 0), 0.5f, 1.0f / 255.0f);

    std::string const dir = test::freshTempDir("gbuffer_layouts_export");
    FrameExport frame{camera_, lights_, s, stats, scene_.triangleCount(), {}};
    ASSERT_FALSE(exportFrame(*renderer_, frame, dir));
    for (char const* f :
         {"raw_normal_oct.exr", "raw_albedo_spec.png", "raw_depth.exr", "position.exr", "normal.exr", "emissive.exr"})
        EXPECT_TRUE(std::filesystem::exists(dir + "/" + f)) << f;
    EXPECT_FALSE(std::filesystem::exists(dir + "/raw_position.exr")) << "packed stores no position";
    EXPECT_FALSE(std::filesystem::exists(dir + "/raw_emissive_ao.png")) << "packed stores no emissive_ao";
    auto const position = readImage(dir + "/position.exr");
    ASSERT_TRUE(position);
    FloatImage const decoded = renderer_->readAttachment(Attachment::Position);
    ASSERT_EQ(position->pixels.size(), decoded.pixels.size());
    EXPECT_EQ(position->pixels, decoded.pixels) << "position.exr is the position the lighting used";
}
