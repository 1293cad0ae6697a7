// Re-lighting an imported G-buffer (issue 28's round trip): the default scene written with
// `render --out`'s export, opened as a G-buffer and re-lit by the import pass, gives the scene's own
// lighting within fp16 rounding in every deferred mode and layout. A wrong light or an image left
// upside down fails the same comparison (so it can fail), and `render --gbuffer` does the same from
// the command line and refuses bad input with exit code 2.
#include "core/gbuffer_layout.h"
#include "frame_export.h"
#include "gl_fixture.h"
#include "import/gbuffer_manifest.h"
#include "import/imported_gbuffer.h"
#include "import/relight_frame.h"
#include "run_command.h"
#include "test_paths.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace gbl;

namespace {

constexpr int kW = 160, kH = 90;
// The lit target is RGBA16F: each stored value is off by up to 2^-11 of itself; a re-lit frame and
// the scene's may round the other way, and the volumes mode rounds once per light it adds.
constexpr double kHalfUlp = 1.0 / 2048.0;

double bound(LightingMode mode, double v) {
    return (mode == LightingMode::Volumes ? 16.0 : 2.0) * kHalfUlp * v + 1e-4;
}

struct Diff {
    double maxAbs = 0.0;
    int pixelsOver = 0;
};

Diff compare(FloatImage const& a, FloatImage const& ref, LightingMode mode) {
    Diff d;
    EXPECT_EQ(a.width, ref.width);
    EXPECT_EQ(a.height, ref.height);
    if (a.width != ref.width || a.height != ref.height) return {1e30, ref.width * ref.height};
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) {
            bool over = false;
            for (int c = 0; c < 3; ++c) {
                double const e = std::abs(double(a.at(x, y, c)) - ref.at(x, y, c));
                d.maxAbs = std::max(d.maxAbs, e);
                over = over || e > bound(mode, std::abs(ref.at(x, y, c)));
            }
            d.pixelsOver += over;
        }
    return d;
}

std::vector<LightingMode> deferredModes(GlCaps const& caps) {
    std::vector<LightingMode> modes{LightingMode::Quad, LightingMode::Volumes};
    if (caps.computeShaders) modes.insert(modes.end(), {LightingMode::Tiled, LightingMode::Clustered});
    return modes;
}

PipelineSettings settingsFor(LightingMode mode, GBufferLayout layout) {
    PipelineSettings s;
    s.mode = mode;
    s.layout = layout;
    s.cull = CullMode::Front;
    s.lightCubes = false;
    return s;
}

class RelightGlTest : public test::CourtyardGlTest {
protected:
    RelightGlTest() : CourtyardGlTest(kW, kH) {}

    // The scene's frame in `layout`, exported as `render --out` does, and opened as a G-buffer.
    ImportedGBuffer exported(GBufferLayout layout) {
        std::string const dir = test::freshTempDir(std::string("relight_") + std::string(layoutDesc(layout).name));
        PipelineSettings const s = settingsFor(LightingMode::Quad, layout);
        FrameStats const stats = renderer_->render({camera_, lights_, s, true});
        EXPECT_FALSE(exportFrame(*renderer_, {camera_, lights_, s, stats, 0, {}}, dir));
        ManifestLoad const m = loadManifest(dir);
        EXPECT_TRUE(m.manifest) << m.error;
        GBufferLoad g = loadGBuffer(*m.manifest);
        EXPECT_TRUE(g.gbuffer) << g.error;
        return std::move(*g.gbuffer);
    }

    FloatImage sceneLighting(LightingMode mode, GBufferLayout layout) {
        FrameStats const st = renderer_->render({camera_, lights_, settingsFor(mode, layout), true});
        EXPECT_EQ(st.modeUsed, mode) << st.fallbackReason;
        return renderer_->readAttachment(Attachment::Lighting);
    }

    // `frame` re-lit with `lights` by a renderer that has no scene.
    FloatImage relit(ImportedFrame const& frame, std::span<PointLight const> lights, LightingMode mode,
                     GBufferLayout layout) {
        auto r = makeRenderer(kW, kH);
        EXPECT_FALSE(r->setImportedGBuffer(frame));
        FrameInput input{Camera{}, lights, settingsFor(mode, layout), true};
        std::vector<PassDecl> const passes = r->framePasses(input);
        EXPECT_EQ(passes.front().id, PassId::Import);
        FrameStats const st = r->render(input);
        EXPECT_EQ(st.modeUsed, mode) << st.fallbackReason;
        EXPECT_EQ(st.glErrors, 0u);
        return r->readAttachment(Attachment::Lighting);
    }
};

TEST_F(RelightGlTest, RoundTripMatchesTheSceneInEveryModeAndLayout) {
    for (GBufferLayout layout :
         {GBufferLayout::Classic, GBufferLayout::Packed, GBufferLayout::Naive8, GBufferLayout::Rgb10a2}) {
        ImportedGBuffer const g = exported(layout);
        RelightFrame const f = relightFrame(g);
        ASSERT_TRUE(f.frame) << f.error;
        std::vector<PointLight> const lights = g.manifest.lights;
        ASSERT_EQ(lights.size(), lights_.size());
        for (LightingMode mode : deferredModes(caps())) {
            FloatImage const ref = sceneLighting(mode, layout);
            Diff const d = compare(relit(*f.frame, lights, mode, layout), ref, mode);
            std::printf("round trip %-9s %-8s max abs error %.3g, pixels over the fp16 bound %d\n",
                        std::string(layoutDesc(layout).name).c_str(),
                        std::string(enumName(kLightingModeNames, mode)).c_str(), d.maxAbs, d.pixelsOver);
            EXPECT_EQ(d.pixelsOver, 0) << layoutDesc(layout).name << " / " << enumName(kLightingModeNames, mode)
                                       << ": max abs error " << d.maxAbs;
        }
    }
}

// The comparison above can fail: a light moved by half a unit, or the frame uploaded top row first
// (the flip the import does left out), puts many pixels over the bound.
TEST_F(RelightGlTest, AWrongLightOrAnUnflippedImageFails) {
    ImportedGBuffer const g = exported(GBufferLayout::Classic);
    RelightFrame const f = relightFrame(g);
    ASSERT_TRUE(f.frame) << f.error;
    FloatImage const ref = sceneLighting(LightingMode::Quad, GBufferLayout::Classic);

    std::vector<PointLight> moved = g.manifest.lights;
    ASSERT_FALSE(moved.empty());
    moved[0].position.x += 0.5f;
    Diff const wrongLight =
        compare(relit(*f.frame, moved, LightingMode::Quad, GBufferLayout::Classic), ref, LightingMode::Quad);
    EXPECT_GT(wrongLight.pixelsOver, 20) << "max abs error " << wrongLight.maxAbs;

    ImportedFrame flipped = *f.frame;
    for (auto* rows : {&flipped.positionDepth, &flipped.normal, &flipped.albedoSpec})
        for (int y = 0; y < kH / 2; ++y)
            std::swap_ranges(rows->begin() + std::ptrdiff_t(y) * kW, rows->begin() + std::ptrdiff_t(y + 1) * kW,
                             rows->begin() + std::ptrdiff_t(kH - 1 - y) * kW);
    Diff const upsideDown =
        compare(relit(flipped, g.manifest.lights, LightingMode::Quad, GBufferLayout::Classic), ref, LightingMode::Quad);
    EXPECT_GT(upsideDown.pixelsOver, kW * kH / 10) << "max abs error " << upsideDown.maxAbs;
}

// The frame declares the import pass in the geometry pass's place, with no feedback loop, in every
// deferred mode and layout; forward mode becomes the quad pass, with the reason.
TEST_F(RelightGlTest, ForwardModeRunsTheQuadPassAndSaysWhy) {
    ImportedGBuffer const g = exported(GBufferLayout::Classic);
    RelightFrame const f = relightFrame(g);
    ASSERT_TRUE(f.frame) << f.error;
    auto r = makeRenderer(kW, kH);
    ASSERT_FALSE(r->setImportedGBuffer(*f.frame));
    PipelineSettings s = settingsFor(LightingMode::Forward, GBufferLayout::Classic);
    FrameStats const st = r->render({Camera{}, g.manifest.lights, s, true});
    EXPECT_EQ(st.modeUsed, LightingMode::Quad);
    EXPECT_NE(st.fallbackReason.find("forward shading draws the scene's meshes"), std::string::npos)
        << st.fallbackReason;
}

// `render --gbuffer DIR --out E` on a `render --out DIR` folder: the same lighting.exr.
TEST(RelightCommand, RenderOutFolderReLitGivesTheSameLighting) {
    std::string const d = test::freshTempDir("relight_cli_in"), e = test::freshTempDir("relight_cli_out");
    auto const a = test::runGbufferLab({"render", "--out", d, "--size", "160x90", "--lights", "8"});
    ASSERT_EQ(a.exitCode, 0) << a.output;
    auto const b = test::runGbufferLab({"render", "--gbuffer", d, "--out", e});
    ASSERT_EQ(b.exitCode, 0) << b.output;
    GBufferLoad const before = loadGBuffer(*loadManifest(d).manifest);
    GBufferLoad const after = loadGBuffer(*loadManifest(e).manifest);
    ASSERT_TRUE(before.gbuffer) << before.error;
    ASSERT_TRUE(after.gbuffer) << after.error;
    ASSERT_EQ(before.gbuffer->lit.size(), after.gbuffer->lit.size());
    int over = 0;
    for (std::size_t p = 0; p < before.gbuffer->lit.size(); ++p)
        for (int c = 0; c < 3; ++c) {
            double const ref = before.gbuffer->lit[p][c], got = after.gbuffer->lit[p][c];
            over += std::abs(got - ref) > bound(LightingMode::Volumes, std::abs(ref));
        }
    EXPECT_EQ(over, 0);
    // The re-lit folder is a G-buffer of its own, with the same camera.
    EXPECT_EQ(after.gbuffer->manifest.lights.size(), before.gbuffer->manifest.lights.size());
}

// `--shading learnopengl` re-lights with that text's equation and ambient 0.1: never darker than
// gbuffer-lab's windowed model at any pixel (its attenuation has no window to subtract, its
// highlight no gate, its ambient is higher), and brighter on the geometry; a bad name is refused.
TEST(RelightCommand, TheLearnOpenGlShadingLightsMoreThanTheWindowedModel) {
    std::string const d = test::freshTempDir("relight_lo_in");
    std::string const ours = test::freshTempDir("relight_lo_ours"), lo = test::freshTempDir("relight_lo_lo");
    auto const a = test::runGbufferLab({"render", "--out", d, "--size", "160x90", "--lights", "8"});
    ASSERT_EQ(a.exitCode, 0) << a.output;
    ASSERT_EQ(test::runGbufferLab({"render", "--gbuffer", d, "--out", ours}).exitCode, 0);
    auto const b = test::runGbufferLab({"render", "--gbuffer", d, "--out", lo, "--shading", "learnopengl"});
    ASSERT_EQ(b.exitCode, 0) << b.output;
    GBufferLoad const windowed = loadGBuffer(*loadManifest(ours).manifest);
    GBufferLoad const classic = loadGBuffer(*loadManifest(lo).manifest);
    ASSERT_TRUE(windowed.gbuffer && classic.gbuffer);
    ASSERT_EQ(windowed.gbuffer->lit.size(), classic.gbuffer->lit.size());
    int darker = 0, brighter = 0, covered = 0;
    for (std::size_t p = 0; p < windowed.gbuffer->lit.size(); ++p) {
        glm::vec3 const w(windowed.gbuffer->lit[p]), c(classic.gbuffer->lit[p]);
        if (w == glm::vec3(0.0f) && c == glm::vec3(0.0f)) continue;  // background
        ++covered;
        for (int k = 0; k < 3; ++k) darker += c[k] < w[k] - bound(LightingMode::Quad, std::abs(w[k]));
        brighter += c.r + c.g + c.b > w.r + w.g + w.b + 0.01f;
    }
    EXPECT_GT(covered, 160 * 90 / 2);
    EXPECT_EQ(darker, 0);
    EXPECT_GT(brighter, covered * 9 / 10);
    test::expectRefused({"render", "--gbuffer", d, "--out", lo, "--shading", "phong"},
                        "--shading must be gbuffer-lab or learnopengl");
}

TEST(RelightCommand, BadInputIsRefusedInOneSentence) {
    std::string const dir = test::freshTempDir("relight_cli_bad");
    test::expectRefused({"render", "--gbuffer", dir + "/none.json", "--out", dir + "/o"}, "cannot read the manifest");
    std::ofstream(dir + "/m.json")
        << R"({"format": "gbuffer-lab-gbuffer", "version": 1, "preset": "learnopengl", "normal": {"encoding": "polar"}})";
    test::expectRefused({"render", "--gbuffer", dir + "/m.json", "--out", dir + "/o"},
                        "normal.encoding must be one of");
    test::expectRefused({"render", "--gbuffer", dir + "/m.json", "--out", dir + "/o", "--mode", "forward"},
                        "--mode forward draws the scene's meshes");
    test::expectRefused({"render", "--gbuffer", dir + "/m.json", "--out", dir + "/o", "--scene", "x.gltf"},
                        "--scene cannot be combined with --gbuffer");
}

}  // namespace
