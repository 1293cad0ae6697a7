// Emission and ambient occlusion of glTF materials in real frames: a handcrafted quad with an
// emissive factor and texture and an occlusion texture, rendered in every layout and lighting
// mode, against the analytic value and against the CPU equation (core/shading_cpu.h).
#include "core/gbuffer_layout.h"
#include "core/shading_cpu.h"
#include "frame_export.h"
#include "gl_fixture.h"
#include "gltf/loader.h"
#include "handmade_gltf.h"
#include "image/image_io.h"
#include "run_command.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace gbl;
using gbl::test::GlTest;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

constexpr int kSize = 48;
constexpr float kTexel128 = 128.0f / 255.0f;
// The material: albedo values that RGBA8 stores exactly (204, 153, 102 / 255).
constexpr glm::vec3 kAlbedo{0.8f, 0.6f, 0.4f};
constexpr glm::vec3 kEmissiveFactor{0.5f, 1.0f, 0.25f};
constexpr float kOcclusionStrength = 0.75f;

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// The emissive texture is (255, 128, 0) sRGB everywhere, so m = factor * (1, 0.2159, 0).
glm::vec3 expectedEmission() {
    return kEmissiveFactor * glm::vec3(1.0f, srgbToLinear(kTexel128), 0.0f);
}
// The occlusion texture is 128 everywhere: ao = 1 + strength * (128/255 - 1) = 0.6265.
float expectedOcclusion() {
    return 1.0f + kOcclusionStrength * (kTexel128 - 1.0f);
}

// A 2x2 quad at z = 0 facing +z, filling the view of a camera at z = 1 with a 90 degree field of view.
std::vector<std::uint8_t> quadDocument() {
    test::HandmadeGltf g;
    json attrs = {{"POSITION", g.floats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, "VEC3")},
                  {"NORMAL", g.floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3")},
                  {"TEXCOORD_0", g.floats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2")}};
    g.doc["images"] = {{{"uri", "emissive.png"}}, {{"uri", "occlusion.png"}}};
    g.doc["textures"] = {{{"source", 0}}, {{"source", 1}}};
    json transform = {{"KHR_texture_transform", {{"offset", {0.25, 0.0}}}}};
    g.doc["materials"] = {{{"pbrMetallicRoughness",
                            {{"baseColorFactor", {kAlbedo.x, kAlbedo.y, kAlbedo.z, 1.0}}, {"metallicFactor", 0.0}}},
                           {"emissiveFactor", {kEmissiveFactor.x, kEmissiveFactor.y, kEmissiveFactor.z}},
                           {"emissiveTexture", {{"index", 0}, {"extensions", transform}}},
                           {"occlusionTexture", {{"index", 1}, {"strength", kOcclusionStrength}, {"texCoord", 0}}}}};
    g.doc["extensionsUsed"] = {"KHR_texture_transform"};
    g.meshNode(json::array({{{"attributes", attrs}, {"indices", g.indices({0, 1, 2, 0, 2, 3})}, {"material", 0}}}));
    return g.bytes();
}

class SurfaceTermsGlTest : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        fs::path const dir = test::freshTempDir("surface_terms");
        FloatImage emissive{2, 2, 3, {}}, occlusion{2, 2, 3, {}};
        for (int i = 0; i < 4; ++i) {
            emissive.pixels.insert(emissive.pixels.end(), {1.0f, kTexel128, 0.0f});
            occlusion.pixels.insert(occlusion.pixels.end(), {kTexel128, kTexel128, kTexel128});
        }
        ASSERT_FALSE(writePng((dir / "emissive.png").string(), emissive));
        ASSERT_FALSE(writePng((dir / "occlusion.png").string(), occlusion));
        auto const bytes = quadDocument();
        std::ofstream((dir / "quad.gltf").string(), std::ios::binary)
            .write(reinterpret_cast<char const*>(bytes.data()), std::streamsize(bytes.size()));
        GltfLoadResult r = loadGltf(dir / "quad.gltf");
        ASSERT_TRUE(r.scene) << r.error;
        scene_ = std::move(*r.scene);
        EXPECT_TRUE(scene_.warnings.empty()) << scene_.warnings.front();
        camera_.position = {0.0f, 0.0f, 1.0f};
        camera_.yawDegrees = -90.0f;
        camera_.pitchDegrees = 0.0f;
        camera_.fovYDegrees = 90.0f;
        renderer_ = makeRenderer(kSize, kSize);
        ASSERT_FALSE(renderer_->setScene(scene_));
    }
    void TearDown() override {
        renderer_.reset();
        GlTest::TearDown();
    }

    static PipelineSettings settings(GBufferLayout layout, LightingMode mode) {
        PipelineSettings s;
        s.layout = layout;
        s.mode = mode;
        s.lightCubes = false;
        s.ambient = glm::vec3(0.5f);  // large enough that occlusion changes it clearly
        return s;
    }

    FloatImage lighting(PipelineSettings const& s, std::vector<PointLight> const& lights) {
        FrameStats const st = renderer_->render({camera_, lights, s, true});
        EXPECT_EQ(st.modeUsed, s.mode) << st.fallbackReason;
        EXPECT_EQ(st.glErrors, 0u);
        return renderer_->readAttachment(Attachment::Lighting);
    }

    std::vector<LightingMode> modes() const {
        std::vector<LightingMode> m{LightingMode::Quad, LightingMode::Volumes, LightingMode::Forward};
        if (caps().computeShaders) m.insert(m.end(), {LightingMode::Tiled, LightingMode::Clustered});
        return m;
    }

    static PointLight light() {
        PointLight l;
        l.position = {0.3f, 0.2f, 0.6f};
        l.color = {1.0f, 0.9f, 0.7f};
        l.intensity = 1.5f;
        l.kl = 0.35f;
        l.kq = 0.44f;
        return l;
    }

    SceneData scene_;
    Camera camera_;
    std::unique_ptr<Renderer> renderer_;
};

std::string what(GBufferLayout layout, LightingMode mode) {
    return std::string(layoutDesc(layout).name) + "/" + std::string(enumName(kLightingModeNames, mode));
}

constexpr std::array<GBufferLayout, 4> kAllLayouts{GBufferLayout::Classic, GBufferLayout::Packed, GBufferLayout::Naive8,
                                                   GBufferLayout::Rgb10a2};

}  // namespace

TEST_F(SurfaceTermsGlTest, LoaderReadsEmissionOcclusionAndTheirMappings) {
    ASSERT_EQ(scene_.materials.size(), 1u);
    Material const& m = scene_.materials[0];
    EXPECT_EQ(m.emissiveFactor, kEmissiveFactor);
    ASSERT_GE(m.emissiveTexture, 0);
    EXPECT_TRUE(scene_.images[std::size_t(m.emissiveTexture)].srgb) << "emission is colour";
    EXPECT_EQ(m.emissiveTransform.offset, glm::vec2(0.25f, 0.0f));
    ASSERT_GE(m.occlusionTexture, 0);
    EXPECT_FALSE(scene_.images[std::size_t(m.occlusionTexture)].srgb) << "occlusion is data";
    EXPECT_FLOAT_EQ(m.occlusionStrength, kOcclusionStrength);
    EXPECT_EQ(m.occlusionTransform.texCoord, 0);
}

// What the layout keeps of the material's emission and occlusion: all of it where it has the
// emissive_ao attachment, nothing in packed (decoded as emission 0, occlusion 1).
glm::vec3 storedEmission(GBufferLayout layout) {
    return storesEmissiveAo(layoutDesc(layout)) ? expectedEmission() : glm::vec3(kNoEmissiveAo);
}
float storedOcclusion(GBufferLayout layout) {
    return storesEmissiveAo(layoutDesc(layout)) ? expectedOcclusion() : kNoEmissiveAo.a;
}

TEST_F(SurfaceTermsGlTest, WithNoLightsEveryModeShowsOccludedAmbientPlusEmission) {
    for (GBufferLayout layout : kAllLayouts)
        for (LightingMode mode : modes()) {
            // packed shows neither emission nor occlusion, in every mode (forward included).
            glm::vec3 const expected = glm::vec3(0.5f) * kAlbedo * storedOcclusion(layout) + storedEmission(layout);
            PipelineSettings const s = settings(layout, mode);
            FloatImage const lit = lighting(s, {});
            int wrong = 0;
            for (int y = 0; y < kSize; ++y)
                for (int x = 0; x < kSize; ++x)
                    for (int c = 0; c < 3; ++c)
                        // 2.5e-3: the RGBA8 emissive_ao attachment of the compact layouts rounds emission
                        // and occlusion to 1/255 (at most 0.5/255 = 2.0e-3 each, occlusion scaled by
                        // 0.5 * albedo <= 0.4), plus the lit image's fp16 (2^-11 relative, < 5e-4 here).
                        if (std::abs(lit.at(x, y, c) - expected[c]) > 2.5e-3f && ++wrong <= 3)
                            ADD_FAILURE() << what(layout, mode) << " pixel (" << x << ", " << y << ") channel " << c
                                          << ": " << lit.at(x, y, c) << ", expected " << expected[c];
            EXPECT_EQ(wrong, 0) << what(layout, mode);
            if (mode == LightingMode::Forward) continue;  // no G-buffer to read back
            // What the G-buffer holds: the emissive attachment, decoded, at the centre.
            FloatImage const em = renderer_->readAttachment(Attachment::Emissive);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(em.at(kSize / 2, kSize / 2, c), storedEmission(layout)[c], 2.0e-3f) << what(layout, mode);
            EXPECT_NEAR(em.at(kSize / 2, kSize / 2, 3), storedOcclusion(layout), 2.0e-3f) << what(layout, mode);
        }
}

TEST_F(SurfaceTermsGlTest, OcclusionScalesTheAmbientTermAndNothingElse) {
    // Without emission, the occluded frame over the open one is ao wherever only ambient lights it.
    scene_.materials[0].emissiveFactor = glm::vec3(0.0f);
    ASSERT_FALSE(renderer_->setScene(scene_));
    PipelineSettings const s = settings(GBufferLayout::Classic, LightingMode::Quad);
    FloatImage const occluded = lighting(s, {});
    FloatImage const occludedLit = lighting(s, {light()});
    scene_.materials[0].occlusionTexture = -1;
    ASSERT_FALSE(renderer_->setScene(scene_));
    FloatImage const open = lighting(s, {});
    FloatImage const openLit = lighting(s, {light()});
    int const x = kSize / 4, y = kSize / 3;
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(open.at(x, y, c), 0.5f * kAlbedo[c], 2e-4f) << "ao = 1 without a texture";
        // fp16 of both values (2^-11 relative each) and the RGBA16F-stored ao: 1e-3 of the ratio.
        EXPECT_NEAR(occluded.at(x, y, c) / open.at(x, y, c), expectedOcclusion(), 1e-3f) << c;
        // The light's part is the same with and without occlusion (fp16 of values up to ~1.5: 2e-3).
        EXPECT_NEAR(occludedLit.at(x, y, c) - occluded.at(x, y, c), openLit.at(x, y, c) - open.at(x, y, c), 2e-3f) << c;
    }
}

TEST_F(SurfaceTermsGlTest, WithALightEveryModeMatchesTheCpuOnTheStoredInputs) {
    std::vector<PointLight> const lights{light()};
    ShadingInputs inputsAt[kSize][kSize];  // classic's decoded inputs, for forward (no G-buffer)
    for (GBufferLayout layout : kAllLayouts)
        for (LightingMode mode : modes()) {
            if (mode == LightingMode::Forward && layout != GBufferLayout::Classic) continue;  // no layout
            PipelineSettings const s = settings(layout, mode);
            FloatImage const lit = lighting(s, lights);
            if (mode != LightingMode::Forward) {
                FloatImage const pos = renderer_->readAttachment(Attachment::Position);
                FloatImage const nrm = renderer_->readAttachment(Attachment::Normal);
                FloatImage const alb = renderer_->readAttachment(Attachment::AlbedoSpec);
                FloatImage const em = renderer_->readAttachment(Attachment::Emissive);
                for (int y = 0; y < kSize; ++y)
                    for (int x = 0; x < kSize; ++x) {
                        ShadingInputs& in = inputsAt[y][x];
                        in.position = {pos.at(x, y, 0), pos.at(x, y, 1), pos.at(x, y, 2)};
                        in.normal = {nrm.at(x, y, 0), nrm.at(x, y, 1), nrm.at(x, y, 2)};
                        in.albedo = {alb.at(x, y, 0), alb.at(x, y, 1), alb.at(x, y, 2)};
                        in.specular = alb.at(x, y, 3);
                        in.emissive = {em.at(x, y, 0), em.at(x, y, 1), em.at(x, y, 2)};
                        in.occlusion = em.at(x, y, 3);
                        if (!storesEmissiveAo(layoutDesc(layout))) {
                            // packed: the CPU value with emissive 0 and ao 1, whatever was read back.
                            EXPECT_EQ(glm::vec4(in.emissive, in.occlusion), kNoEmissiveAo) << x << " " << y;
                            in.emissive = glm::vec3(0.0f);
                            in.occlusion = 1.0f;
                        }
                        in.viewPosition = camera_.position;
                        in.shininess = s.shininess;
                    }
            }
            int over = 0;
            double maxErr = 0.0;
            for (int y = 0; y < kSize; ++y)
                for (int x = 0; x < kSize; ++x) {
                    glm::vec3 const expected = shadePointCpu(lights, inputsAt[y][x], s.ambient);
                    for (int c = 0; c < 3; ++c) {
                        // The bound of gbuffer_layouts_gl_test: fp16 storage and blending (8e-3 relative)
                        // plus 1e-3 for pow() on the GPU against the CPU. Forward evaluates the material
                        // itself; classic's stored inputs differ from it by fp16 rounding of position.
                        double const e = std::abs(double(lit.at(x, y, c)) - expected[c]);
                        maxErr = std::max(maxErr, e);
                        over += e > 8e-3 * std::abs(expected[c]) + 1e-3;
                    }
                }
            EXPECT_EQ(over, 0) << what(layout, mode) << ": max error " << maxErr;
        }
}

TEST_F(SurfaceTermsGlTest, OneLightsContributionLeavesEmissionAndAmbientOut) {
    std::vector<PointLight> const lights{light()};
    PipelineSettings const s = settings(GBufferLayout::Classic, LightingMode::Quad);
    FrameInput in{camera_, lights, s, true};
    in.accumulateLights = 1;
    in.lightContribution = true;
    in.outlineAccumulated = false;
    renderer_->render(in);
    FloatImage const lit = renderer_->readAttachment(Attachment::Lighting);
    FloatImage const pos = renderer_->readAttachment(Attachment::Position);
    int const x = kSize / 2, y = kSize / 2;
    ShadingInputs si;
    si.position = {pos.at(x, y, 0), pos.at(x, y, 1), pos.at(x, y, 2)};
    si.normal = {0.0f, 0.0f, 1.0f};
    si.albedo = kAlbedo;
    si.specular = renderer_->readAttachment(Attachment::AlbedoSpec).at(x, y, 3);
    si.viewPosition = camera_.position;
    glm::vec3 const alone = shadeLightCpu(lights[0], si).total();
    for (int c = 0; c < 3; ++c)
        // fp16 of a value below 2 (1e-3) and pow() on the GPU (1e-3), as accumulate_gl_test.
        EXPECT_NEAR(lit.at(x, y, c), alone[c], 2e-3f) << c;
}

TEST_F(SurfaceTermsGlTest, ExportWritesTheDecodedEmissionAndTheRawAttachment) {
    PipelineSettings const s = settings(GBufferLayout::Rgb10a2, LightingMode::Quad);
    FrameStats const stats = renderer_->render({camera_, {}, s, true});
    std::string const dir = test::freshTempDir("surface_terms_export");
    FrameExport frame{camera_, {}, s, stats, scene_.triangleCount(), {DebugView::Emissive, DebugView::Occlusion}};
    ASSERT_FALSE(exportFrame(*renderer_, frame, dir));
    auto const emissive = readImage(dir + "/emissive.exr");
    ASSERT_TRUE(emissive);
    ASSERT_EQ(emissive->channels, 4);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(emissive->at(kSize / 2, kSize / 2, c), expectedEmission()[c], 2e-3f);
    EXPECT_NEAR(emissive->at(kSize / 2, kSize / 2, 3), expectedOcclusion(), 2e-3f);
    EXPECT_TRUE(fs::exists(dir + "/raw_emissive_ao.png"));
    auto const view = readImage(dir + "/view_occlusion.png");
    ASSERT_TRUE(view);
    // The occlusion view remaps [0, 1] to grey: 0.6265 within two 8-bit steps (store and display).
    EXPECT_NEAR(view->at(kSize / 2, kSize / 2, 0), expectedOcclusion(), 2.0f / 255.0f);
    std::ifstream statsFile(dir + "/stats.json");
    EXPECT_FALSE(json::parse(statsFile).contains("gbuffer_note")) << "rgb10a2 stores emission and occlusion";
}

TEST_F(SurfaceTermsGlTest, PackedStoresNoEmissionOrOcclusionAndSaysSo) {
    PipelineSettings const s = settings(GBufferLayout::Packed, LightingMode::Quad);
    FrameStats const stats = renderer_->render({camera_, {}, s, true});
    EXPECT_EQ(stats.glErrors, 0u);
    std::string const dir = test::freshTempDir("surface_terms_packed_export");
    FrameExport frame{camera_, {}, s, stats, scene_.triangleCount(), {DebugView::Emissive, DebugView::Occlusion}};
    ASSERT_FALSE(exportFrame(*renderer_, frame, dir));
    // emissive.exr is what packed decodes: emission 0 and occlusion 1 at every pixel (exact).
    auto const emissive = readImage(dir + "/emissive.exr");
    ASSERT_TRUE(emissive);
    ASSERT_EQ(emissive->channels, 4);
    for (int y = 0; y < kSize; y += 7)
        for (int x = 0; x < kSize; x += 7)
            for (int c = 0; c < 4; ++c) ASSERT_EQ(emissive->at(x, y, c), kNoEmissiveAo[c]) << x << " " << y << " " << c;
    EXPECT_FALSE(fs::exists(dir + "/raw_emissive_ao.png")) << "the raw files follow the layout's attachments";
    EXPECT_FALSE(fs::exists(dir + "/raw_emissive_ao.exr"));
    auto const emissiveView = readImage(dir + "/view_emissive.png");
    auto const occlusionView = readImage(dir + "/view_occlusion.png");
    ASSERT_TRUE(emissiveView && occlusionView);
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(emissiveView->at(kSize / 2, kSize / 2, c), 0.0f) << c;
        EXPECT_EQ(occlusionView->at(kSize / 2, kSize / 2, c), 1.0f) << c;
    }
    std::ifstream statsFile(dir + "/stats.json");
    json const st = json::parse(statsFile);
    EXPECT_EQ(st["gbuffer_bytes_per_pixel"], 12);
    EXPECT_EQ(st["gbuffer_note"], layoutOmissionNote(layoutDesc(GBufferLayout::Packed)));
    // The inspector's sample decodes the same: emission 0, occlusion 1.
    PixelSample const px = renderer_->samplePixel(kSize / 2, kSize / 2, camera_);
    EXPECT_TRUE(px.covered);
    EXPECT_EQ(px.emissiveAo, kNoEmissiveAo);
}
