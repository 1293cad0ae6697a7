// Re-lighting an imported G-buffer (issue 28's round trip): the default scene written with
// `render --out`'s export, opened as a G-buffer and re-lit by the import pass, gives the scene's own
// lighting within fp16 rounding in every deferred mode and layout. A wrong light or an image left
// upside down fails the same comparison (so it can fail), and `render --gbuffer` does the same from
// the command line and refuses bad input with exit code 2.
#include "core/gbuffer_layout.h"
#include "core/shading_cpu.h"
#include "frame_export.h"
#include "gl_fixture.h"
#include "import/gbuffer_manifest.h"
#include "import/imported_gbuffer.h"
#include "import/relight_frame.h"
#include "run_command.h"
#include "test_paths.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

using namespace gbl;

namespace {

constexpr int kW = 160, kH = 90;
// The lit target is RGBA16F: each stored value is off by up to 2^-11 of itself; a re-lit frame and
// the scene's may round the other way, and the volumes mode rounds once per light it adds.
constexpr double kHalfUlp = 1.0 / 2048.0;

double bound(LightingMode mode, double v) {
    return (mode == LightingMode::Volumes ? 16.0 : 2.0) * kHalfUlp * v + 1e-4;
}

// Lit channels of a re-lit G-buffer farther from the original's than `mode`'s bound (every pixel when the
// sizes differ).
int litChannelsOverBound(ImportedGBuffer const& original, ImportedGBuffer const& relit, LightingMode mode) {
    EXPECT_EQ(relit.lit.size(), original.lit.size());
    if (relit.lit.size() != original.lit.size()) return int(original.lit.size()) * 3;
    int over = 0;
    for (std::size_t p = 0; p < original.lit.size(); ++p)
        for (int c = 0; c < 3; ++c) {
            double const ref = original.lit[p][c], got = relit.lit[p][c];
            over += std::abs(got - ref) > bound(mode, std::abs(ref));
        }
    return over;
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

PipelineSettings settingsFor(LightingMode mode, GBufferLayout layout, glm::vec3 ambient = PipelineSettings{}.ambient) {
    PipelineSettings s;
    s.mode = mode;
    s.layout = layout;
    s.cull = CullMode::Front;
    s.lightCubes = false;
    s.ambient = ambient;
    return s;
}

constexpr std::array<GBufferLayout, 4> kLayouts{GBufferLayout::Classic, GBufferLayout::Packed, GBufferLayout::Naive8,
                                                GBufferLayout::Rgb10a2};

// What the layout's emissive_ao attachment keeps of (emission, occlusion): RGBA16F all of it (to
// fp16), RGBA8 [0, 1] in 1/255 steps, and a layout without one (packed) nothing: kNoEmissiveAo.
glm::vec4 keptByLayout(GBufferLayout layout, glm::vec4 v) {
    GBufferLayoutDesc const& d = layoutDesc(layout);
    int const index = colorAttachmentIndex(d, GBufferSlot::Emissive);
    if (index < 0) return kNoEmissiveAo;
    if (d.attachmentArray[std::size_t(index)].format == TexelFormat::RGBA8)
        return glm::round(glm::clamp(v, 0.0f, 1.0f) * 255.0f) / 255.0f;
    return v;
}

// The courtyard with emission and occlusion (it has neither): the flagstones, wood and marble emit
// (the sandstone above 1 in red, which the RGBA8 layouts clamp), the other materials carry a 2x2
// occlusion texture of four levels.
void addEmissionAndOcclusion(SceneData& scene) {
    ImageData ao;
    ao.name = "relight test occlusion";
    ao.width = ao.height = 2;
    ao.channels = 4;
    ao.pixels = {64, 64, 64, 255, 255, 255, 255, 255, 160, 160, 160, 255, 16, 16, 16, 255};
    scene.images.push_back(ao);
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        Material& m = scene.materials[i];
        if (i % 3 == 0) m.emissiveFactor = {0.5f, 0.25f, 0.125f};
        if (i == 2) m.emissiveFactor = {1.5f, 0.3f, 0.0f};
        if (i % 3 == 1) {
            m.occlusionTexture = int(scene.images.size()) - 1;
            m.occlusionStrength = 0.9f;
        }
    }
}

class RelightGlTest : public test::CourtyardGlTest {
protected:
    RelightGlTest() : CourtyardGlTest(kW, kH) {}

    // The scene's frame in `layout`, exported as `render --out` does, and opened as a G-buffer.
    ImportedGBuffer exported(GBufferLayout layout) {
        std::string const dir = test::freshTempDir(std::string("relight_") + std::string(layoutDesc(layout).name));
        PipelineSettings const s = settingsFor(LightingMode::Quad, layout, ambient_);
        FrameStats const stats = renderer_->render({camera_, lights_, s, true});
        EXPECT_FALSE(exportFrame(*renderer_, {camera_, lights_, s, stats, 0, {}}, dir));
        ManifestLoad const m = loadManifest(dir);
        EXPECT_TRUE(m.manifest) << m.error;
        GBufferLoad g = loadGBuffer(*m.manifest);
        EXPECT_TRUE(g.gbuffer) << g.error;
        return std::move(*g.gbuffer);
    }

    FloatImage sceneLighting(LightingMode mode, GBufferLayout layout) {
        FrameStats const st = renderer_->render({camera_, lights_, settingsFor(mode, layout, ambient_), true});
        EXPECT_EQ(st.modeUsed, mode) << st.fallbackReason;
        return renderer_->readAttachment(Attachment::Lighting);
    }

    // `frame` re-lit with `lights` by a renderer that has no scene; `sample` (optional) receives the
    // pixel inspector's sample at (x, y) from the top-left of the re-lit G-buffer.
    FloatImage relit(ImportedFrame const& frame, std::span<PointLight const> lights, LightingMode mode,
                     GBufferLayout layout, std::optional<glm::ivec2> at = std::nullopt, PixelSample* sample = nullptr) {
        auto r = makeRenderer(kW, kH);
        EXPECT_FALSE(r->setImportedGBuffer(frame));
        FrameInput input{Camera{}, lights, settingsFor(mode, layout, ambient_), true};
        std::vector<PassDecl> const passes = r->framePasses(input);
        EXPECT_EQ(passes.front().id, PassId::Import);
        FrameStats const st = r->render(input);
        EXPECT_EQ(st.modeUsed, mode) << st.fallbackReason;
        EXPECT_EQ(st.glErrors, 0u);
        if (at && sample) *sample = r->samplePixel(at->x, at->y, cameraOfFrame(frame));
        return r->readAttachment(Attachment::Lighting);
    }

    // Every layout exported, opened and re-lit in every deferred mode, against the scene's own
    // lighting in that mode and layout. With `emission`, also checks that the export kept some.
    void expectRoundTrip(bool emission) {
        for (GBufferLayout layout : kLayouts) {
            ImportedGBuffer const g = exported(layout);
            if (emission && storesEmissiveAo(layoutDesc(layout))) {
                // Not a vacuous comparison: the folder holds emission and occlusion below 1.
                EXPECT_GT(std::count_if(g.emissive.begin(), g.emissive.end(), [](glm::vec3 e) { return e.r > 0.1f; }),
                          kW * kH / 20);
                EXPECT_GT(std::count_if(g.occlusion.begin(), g.occlusion.end(), [](float o) { return o < 0.9f; }),
                          kW * kH / 20);
            }
            RelightFrame const f = relightFrame(g);
            ASSERT_TRUE(f.frame) << f.error;
            std::vector<PointLight> const lights = g.manifest.lights;
            ASSERT_EQ(lights.size(), lights_.size());
            for (LightingMode mode : deferredModes(caps())) {
                FloatImage const ref = sceneLighting(mode, layout);
                Diff const d = compare(relit(*f.frame, lights, mode, layout), ref, mode);
                std::printf("round trip%s %-9s %-8s max abs error %.3g, pixels over the fp16 bound %d\n",
                            emission ? " (emission, occlusion)" : "", std::string(layoutDesc(layout).name).c_str(),
                            std::string(enumName(kLightingModeNames, mode)).c_str(), d.maxAbs, d.pixelsOver);
                EXPECT_EQ(d.pixelsOver, 0) << layoutDesc(layout).name << " / " << enumName(kLightingModeNames, mode)
                                           << ": max abs error " << d.maxAbs;
            }
        }
    }

    glm::vec3 ambient_ = PipelineSettings{}.ambient;
};

TEST_F(RelightGlTest, RoundTripMatchesTheSceneInEveryModeAndLayout) {
    expectRoundTrip(false);
}

// The same with emission and occlusion in the scene, and an ambient (0.3) that makes occlusion
// matter: the export's emissive.exr carries them into the re-light in every layout that stores
// them (packed stores neither, in the scene's frame as in the re-lit one). Leaving them out of the
// re-light puts pixels over the bound.
TEST_F(RelightGlTest, RoundTripKeepsEmissionAndOcclusionInEveryModeAndLayout) {
    addEmissionAndOcclusion(scene_);
    ASSERT_FALSE(renderer_->setScene(scene_));
    ambient_ = glm::vec3(0.3f);
    expectRoundTrip(true);

    ImportedGBuffer const g = exported(GBufferLayout::Classic);
    RelightFrame f = relightFrame(g);
    ASSERT_TRUE(f.frame) << f.error;
    f.frame->emissiveAo.clear();  // emission 0, occlusion 1: the import pass of before
    FloatImage const ref = sceneLighting(LightingMode::Quad, GBufferLayout::Classic);
    Diff const without = compare(relit(*f.frame, g.manifest.lights, LightingMode::Quad, GBufferLayout::Classic), ref,
                                 LightingMode::Quad);
    EXPECT_GT(without.pixelsOver, kW * kH / 10) << "max abs error " << without.maxAbs;
}

// On the courtyard's exported G-buffer (no emission, occlusion 1), an emissive patch and an
// occluded patch added to the manifest's images change the re-lit frame by the CPU's surface terms
// (core/shading_cpu.h) of what the layout keeps of them, there and nowhere else, in every mode and
// layout; the pixel inspector's sample holds those values, and the CPU sum of it is the GL's pixel.
TEST_F(RelightGlTest, AnEmissivePatchAndAnOccludedPatchChangeTheFrameAsTheCpuSays) {
    ambient_ = glm::vec3(0.5f);  // large enough that occlusion changes the frame clearly
    // Blue above 1: classic keeps it, the RGBA8 layouts clamp it to 1.
    glm::vec3 const emission(0.6f, 0.35f, 2.5f);
    float const occlusion = 0.25f;
    auto inEmissive = [](int x, int y) { return x >= 30 && x < 60 && y >= 40 && y < 70; };
    auto inOccluded = [](int x, int y) { return x >= 100 && x < 130 && y >= 40 && y < 70; };
    for (GBufferLayout layout : kLayouts) {
        ImportedGBuffer g = exported(layout);
        RelightFrame const plain = relightFrame(g);
        ASSERT_TRUE(plain.frame) << plain.error;
        std::size_t const n = g.pixelCount();
        g.emissive.assign(n, glm::vec3(0.0f));
        g.occlusion.assign(n, 1.0f);
        int covered[2] = {0, 0};
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                std::size_t const p = std::size_t(y * kW + x);
                if (inEmissive(x, y)) g.emissive[p] = emission;
                if (inOccluded(x, y)) g.occlusion[p] = occlusion;
                covered[0] += inEmissive(x, y) && !g.background[p];
                covered[1] += inOccluded(x, y) && !g.background[p];
            }
        ASSERT_GT(covered[0], 300);  // the patches lie on the courtyard, not the sky
        ASSERT_GT(covered[1], 300);
        RelightFrame const patched = relightFrame(g);
        ASSERT_TRUE(patched.frame) << patched.error;
        glm::vec4 const keptEmission = keptByLayout(layout, glm::vec4(emission, 1.0f));
        glm::vec4 const keptOcclusion = keptByLayout(layout, glm::vec4(0.0f, 0.0f, 0.0f, occlusion));
        for (LightingMode mode : deferredModes(caps())) {
            std::string const what =
                std::string(layoutDesc(layout).name) + " / " + std::string(enumName(kLightingModeNames, mode));
            glm::ivec2 const emissivePixel(45, 55), occludedPixel(115, 55);
            PixelSample atEmissive, atOccluded;
            FloatImage const before = relit(*plain.frame, g.manifest.lights, mode, layout);
            FloatImage const after = relit(*patched.frame, g.manifest.lights, mode, layout, emissivePixel, &atEmissive);
            relit(*patched.frame, g.manifest.lights, mode, layout, occludedPixel, &atOccluded);
            int over = 0;
            double largest = 0.0;
            for (int y = 0; y < kH; ++y)
                for (int x = 0; x < kW; ++x) {
                    std::size_t const p = std::size_t(y * kW + x);
                    ShadingInputs open, changed;
                    open.albedo = changed.albedo = g.albedo[p];  // 8-bit in albedo.png: stored exactly
                    if (inEmissive(x, y)) changed.emissive = glm::vec3(keptEmission);
                    if (inOccluded(x, y)) changed.occlusion = keptOcclusion.a;
                    glm::vec3 const expected =
                        g.background[p] ? glm::vec3(0.0f)
                                        : surfaceTermsCpu(changed, ambient_) - surfaceTermsCpu(open, ambient_);
                    for (int c = 0; c < 3; ++c) {
                        double const got = double(after.at(x, y, c)) - before.at(x, y, c);
                        double const e = std::abs(got - expected[c]);
                        largest = std::max(largest, e);
                        // Each frame's fp16 rounding (the bound of the round trip), and classic's
                        // RGBA16F emission (one ulp, 2^-10 of it: see the sample below).
                        over += e > bound(mode, std::abs(after.at(x, y, c))) +
                                        bound(mode, std::abs(before.at(x, y, c))) + 2 * kHalfUlp * expected[c];
                    }
                }
            EXPECT_EQ(over, 0) << what << ": largest difference from the CPU's change " << largest;
            // The inspector reads what the layout kept, and the CPU sum over it is the GL's pixel.
            // RGBA16F: llvmpipe rounds toward zero (0.6 is stored as 0.59961), one ulp, 2^-10 of the
            // value; RGBA8 holds the kept value itself.
            for (int c = 0; c < 4; ++c) {
                EXPECT_NEAR(atEmissive.emissiveAo[c], keptEmission[c], 2 * kHalfUlp * keptEmission[c] + 1e-6) << what;
                EXPECT_NEAR(atOccluded.emissiveAo[c], keptOcclusion[c], 2 * kHalfUlp * keptOcclusion[c] + 1e-6) << what;
            }
            for (auto [at, sample] : {std::pair{emissivePixel, &atEmissive}, std::pair{occludedPixel, &atOccluded}}) {
                ASSERT_TRUE(sample->covered) << what;
                ShadingInputs in;
                in.position = glm::vec3(sample->position);
                in.normal = glm::vec3(sample->normal);
                in.albedo = glm::vec3(sample->albedoSpec);
                in.specular = sample->albedoSpec.a;
                in.emissive = glm::vec3(sample->emissiveAo);
                in.occlusion = sample->emissiveAo.a;
                in.viewPosition = plain.frame->eye;
                shadingOf(settingsFor(mode, layout, ambient_), in);
                glm::vec3 const cpu = shadePointCpu(g.manifest.lights, in, ambient_);
                for (int c = 0; c < 3; ++c)
                    // surface_terms_gl_test's bound: fp16 storage and blending (8e-3 relative) and
                    // pow() on the GPU (1e-3).
                    EXPECT_NEAR(after.at(at.x, at.y, c), cpu[c], 8e-3 * std::abs(cpu[c]) + 1e-3)
                        << what << " pixel (" << at.x << ", " << at.y << ") channel " << c;
            }
        }
    }
}

// `render --gbuffer D --out E` on that courtyard exported to D: E's lighting.exr is D's (the scene's
// own), with the RGBA16F (classic) and an RGBA8 (rgb10a2) emissive_ao attachment.
TEST_F(RelightGlTest, RenderGbufferCommandKeepsEmissionAndOcclusion) {
    addEmissionAndOcclusion(scene_);
    ASSERT_FALSE(renderer_->setScene(scene_));
    for (GBufferLayout layout : {GBufferLayout::Classic, GBufferLayout::Rgb10a2}) {
        std::string const name(layoutDesc(layout).name);
        std::string const d = test::freshTempDir("relight_cli_emissive_in_" + name);
        std::string const e = test::freshTempDir("relight_cli_emissive_out_" + name);
        PipelineSettings const s = settingsFor(LightingMode::Quad, layout);
        FrameStats const stats = renderer_->render({camera_, lights_, s, true});
        ASSERT_FALSE(exportFrame(*renderer_, {camera_, lights_, s, stats, 0, {}}, d));
        auto const r = test::runGbufferLab({"render", "--gbuffer", d, "--out", e, "--layout", name});
        ASSERT_EQ(r.exitCode, 0) << r.output;
        GBufferLoad const before = loadGBuffer(*loadManifest(d).manifest);
        GBufferLoad const after = loadGBuffer(*loadManifest(e).manifest);
        ASSERT_TRUE(before.gbuffer) << before.error;
        ASSERT_TRUE(after.gbuffer) << after.error;
        EXPECT_EQ(litChannelsOverBound(*before.gbuffer, *after.gbuffer, LightingMode::Quad), 0) << name;
        // The re-lit folder holds the same emission and occlusion again.
        EXPECT_EQ(after.gbuffer->emissive, before.gbuffer->emissive) << name;
        EXPECT_EQ(after.gbuffer->occlusion, before.gbuffer->occlusion) << name;
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
    EXPECT_EQ(litChannelsOverBound(*before.gbuffer, *after.gbuffer, LightingMode::Volumes), 0);
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
                        "--shading: 'phong' is not one of gbuffer-lab or learnopengl");
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
    // prepass's second geometry pass draws the meshes too.
    test::expectRefused({"render", "--gbuffer", dir + "/m.json", "--out", dir + "/o", "--mode", "prepass"},
                        "--mode prepass draws the scene's meshes, and a G-buffer has none: use quad, volumes, tiled or "
                        "clustered");
    test::expectRefused({"render", "--gbuffer", dir + "/m.json", "--out", dir + "/o", "--scene", "x.gltf"},
                        "--scene cannot be combined with --gbuffer");
}

}  // namespace
