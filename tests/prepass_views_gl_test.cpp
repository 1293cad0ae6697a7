// prepass's thin G-buffer in the viewers (issue 48): after a prepass frame the normal, specular,
// depth and position views and read-backs show prepass.normal_exp and the lit depth (the floor's
// +Y normal, the exponent, the depth its rays meet it at), not the layout's G-buffer an earlier frame
// left; the pixel inspector reads the same values; `render`'s export writes the thin attachments.
#include "core/depth.h"
#include "frame_export.h"
#include "gl_fixture.h"
#include "image/image_io.h"
#include "run_command.h"
#include "test_scenes.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

using namespace gbl;

namespace {

constexpr int kW = 160, kH = 90;

class PrepassViewsGlTest : public test::GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        renderer_ = makeRenderer(kW, kH);
        ASSERT_FALSE(renderer_->setScene(test::floorScene()));
        PointLight light;
        light.position = {1.0f, 1.5f, 0.0f};
        lights_ = {light};
        settings_.mode = LightingMode::Prepass;
        settings_.lightCubes = false;
        settings_.shininess = 24.0f;  // not the default 32: the exponent read back is the frame's
    }

    // A quad frame from another camera first, so the layout's G-buffer holds a stale floor that a
    // view still reading it would show; then the prepass frame.
    FrameStats renderPrepass() {
        PipelineSettings quad = settings_;
        quad.mode = LightingMode::Quad;
        EXPECT_EQ(renderer_->render({test::lookingAt({5.0f, 3.0f, 9.0f}, {0.0f, 0.0f, 0.0f}), lights_, quad}).glErrors,
                  0u);
        FrameStats const st = renderer_->render({camera_, lights_, settings_});
        EXPECT_EQ(st.modeUsed, LightingMode::Prepass) << st.fallbackReason;
        EXPECT_EQ(st.glErrors, 0u);
        return st;
    }

    FloatImage view(DebugView v, float lo, float hi) {
        ViewParams p;
        p.view = v;
        p.rangeMin = lo;
        p.rangeMax = hi;
        ViewTarget t;
        renderer_->drawView(p, {camera_, lights_, settings_}, t);
        return renderer_->readViewTarget(t);
    }

    // Where pixel (x, y)'s ray (top-left origin) meets the floor's plane: on the 40 x 40 floor or
    // past its edge (the sky); nullopt where it points up.
    std::optional<glm::vec3> planeAt(int x, int y) const {
        test::Ray const ray = test::pixelRay(camera_, kW, kH, x, y);
        if (ray.dir.y >= -1e-3f) return std::nullopt;
        return ray.origin + ray.dir * (-ray.origin.y / ray.dir.y);
    }
    static float edgeDistance(glm::vec3 p) { return 20.0f - std::max(std::abs(p.x), std::abs(p.z)); }
    std::optional<glm::vec3> floorAt(int x, int y) const {
        std::optional<glm::vec3> const p = planeAt(x, y);
        return p && edgeDistance(*p) > 0.0f ? p : std::nullopt;
    }

    // The window depth of a world point (GL's default depth range).
    float windowDepth(glm::vec3 p) const {
        glm::vec4 const clip = camera_.projection(float(kW) / float(kH)) * camera_.view() * glm::vec4(p, 1.0f);
        return clip.z / clip.w * 0.5f + 0.5f;
    }

    std::unique_ptr<Renderer> renderer_;
    std::vector<PointLight> lights_;
    PipelineSettings settings_;
    // Looking down at the floor and past its far edge, so the frame holds floor and sky.
    Camera camera_ = test::lookingAt({0.0f, 3.0f, 12.0f}, {0.0f, 0.0f, -20.0f});
};

TEST_F(PrepassViewsGlTest, ViewersReadTheThinGBufferOfAPrepassFrame) {
    renderPrepass();
    FloatImage const thin = renderer_->readAttachment(Attachment::PrepassNormal);
    FloatImage const normal = renderer_->readAttachment(Attachment::Normal);
    FloatImage const depth = renderer_->readAttachment(Attachment::Depth);
    FloatImage const position = renderer_->readAttachment(Attachment::Position);
    FloatImage const spec = renderer_->readAttachment(Attachment::AlbedoSpec);
    ASSERT_EQ(thin.channels, 4);
    ASSERT_EQ(depth.channels, 1);
    ASSERT_EQ(thin.pixels.size(), std::size_t(kW) * kH * 4);
    // The views: normal biased into 0..1 (the normal viewer's default), depth over the floor's
    // range, the exponent over 0..48, position's height over -1..1.
    float dMin = 1.0f, dMax = 0.0f;
    for (float d : depth.pixels)
        if (d < 1.0f) dMin = std::min(dMin, d), dMax = std::max(dMax, d);
    ASSERT_LT(dMin, dMax);
    FloatImage const normalView = view(DebugView::Normal, 0.0f, 1.0f);
    FloatImage const depthView = view(DebugView::Depth, dMin, dMax);
    FloatImage const specView = view(DebugView::Specular, 0.0f, 48.0f);
    FloatImage const positionView = view(DebugView::Position, -1.0f, 1.0f);
    int floor = 0, sky = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            std::optional<glm::vec3> const plane = planeAt(x, y);
            // Pixels whose centre ray meets the plane near the floor's edge may be floor or sky: skip.
            if (plane && std::abs(edgeDistance(*plane)) < 0.5f) continue;
            std::optional<glm::vec3> const hit = floorAt(x, y);
            SCOPED_TRACE("pixel " + std::to_string(x) + "," + std::to_string(y));
            float const d = depth.at(x, y, 0);
            // The normal viewer's source is the thin target's normal, texel for texel.
            for (int c = 0; c < 3; ++c) ASSERT_EQ(normal.at(x, y, c), thin.at(x, y, c));
            // The views: 8-bit colours of those values, within one step and a rounding.
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(normalView.at(x, y, c), thin.at(x, y, c) * 0.5f + 0.5f, 1.5f / 255.0f);
            if (!hit) {
                ++sky;
                ASSERT_EQ(d, 1.0f);                   // cleared: nothing drawn
                ASSERT_EQ(normal.at(x, y, 3), 0.0f);  // and read as not drawn
                continue;
            }
            ++floor;
            // The floor faces +Y; fp16 stores 1 exactly and 0 exactly.
            ASSERT_NEAR(thin.at(x, y, 0), 0.0f, 1e-3f);
            ASSERT_NEAR(thin.at(x, y, 1), 1.0f, 1e-3f);
            ASSERT_NEAR(thin.at(x, y, 2), 0.0f, 1e-3f);
            ASSERT_EQ(thin.at(x, y, 3), settings_.shininess);  // 24 is exact in fp16
            ASSERT_EQ(normal.at(x, y, 3), 1.0f);
            // The depth view's source is the lit depth the thin pass wrote: the depth of the point
            // the pixel's ray meets the floor at (a 32-bit float depth, 1e-5 for the rasteriser's
            // interpolation at the pixel centre against the CPU's float projection).
            ASSERT_NEAR(d, windowDepth(*hit), 1e-5f);
            ASSERT_NEAR(depthView.at(x, y, 0), std::clamp((d - dMin) / (dMax - dMin), 0.0f, 1.0f), 1.5f / 255.0f);
            // Position rebuilt from that depth: on the floor, where the ray meets it (the depth's
            // float precision over a 20-unit view: 1e-3 of the distance).
            float const far = glm::length(*hit - camera_.position);
            ASSERT_NEAR(position.at(x, y, 0), hit->x, 1e-3f * far);
            ASSERT_NEAR(position.at(x, y, 1), 0.0f, 1e-3f * far);
            ASSERT_NEAR(position.at(x, y, 2), hit->z, 1e-3f * far);
            ASSERT_NEAR(positionView.at(x, y, 1), 0.5f, 1.5f / 255.0f + 5e-4f * far);
            // No albedo stored; the specular viewer's channel (alpha) is the exponent.
            ASSERT_EQ(spec.at(x, y, 0), 0.0f);
            ASSERT_EQ(spec.at(x, y, 3), settings_.shininess);
            ASSERT_NEAR(specView.at(x, y, 0), settings_.shininess / 48.0f, 1.5f / 255.0f);
        }
    EXPECT_GT(floor, kW * kH / 3);
    EXPECT_GT(sky, kW * 5);
}

TEST_F(PrepassViewsGlTest, PixelInspectorReadsTheSameThinValues) {
    renderPrepass();
    FloatImage const thin = renderer_->readAttachment(Attachment::PrepassNormal);
    FloatImage const depth = renderer_->readAttachment(Attachment::Depth);
    FloatImage const position = renderer_->readAttachment(Attachment::Position);
    int const x = kW / 2, y = kH - 10;  // the floor near the camera
    ASSERT_TRUE(floorAt(x, y));
    PixelSample const s = renderer_->samplePixel(x, y, camera_);
    EXPECT_TRUE(s.thinGBuffer);
    EXPECT_TRUE(s.covered);
    for (int c = 0; c < 4; ++c) EXPECT_EQ(s.rawNormal[c], thin.at(x, y, c)) << c;
    for (int c = 0; c < 3; ++c) EXPECT_EQ(s.normal[c], thin.at(x, y, c)) << c;
    EXPECT_EQ(s.depth, depth.at(x, y, 0));
    EXPECT_EQ(s.albedoSpec, glm::vec4(0.0f, 0.0f, 0.0f, settings_.shininess));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.position[c], position.at(x, y, c), 1e-5f) << c;
    PixelSample const skyPixel = renderer_->samplePixel(x, 2, camera_);
    EXPECT_FALSE(skyPixel.covered);
    EXPECT_EQ(skyPixel.depth, 1.0f);
    // A quad frame reads the layout's G-buffer again.
    PipelineSettings quad = settings_;
    quad.mode = LightingMode::Quad;
    renderer_->render({camera_, lights_, quad});
    EXPECT_FALSE(renderer_->samplePixel(x, y, camera_).thinGBuffer);
}

// `render --mode prepass --out DIR` (exportFrame): the thin attachments under their own names, the
// light targets, and none of the layout's images, which the frame never drew.
TEST_F(PrepassViewsGlTest, ExportWritesTheThinAttachments) {
    FrameStats const st = renderPrepass();
    std::string const dir = test::freshTempDir("prepass_views_export");
    ASSERT_FALSE(exportFrame(*renderer_, {camera_, lights_, settings_, st, 2, {}}, dir));
    for (char const* f :
         {"normal.exr", "specular_exponent.exr", "raw_prepass_normal_exp.exr", "depth.exr", "depth_linear.exr",
          "position.exr", "diffuse_light.exr", "specular_light.exr", "lighting.exr", "final.png"})
        EXPECT_TRUE(std::filesystem::exists(dir + "/" + f)) << f;
    for (char const* f : {"albedo.png", "specular.png", "emissive.exr"})
        EXPECT_FALSE(std::filesystem::exists(dir + "/" + f)) << f;
    for (GBufferAttachmentDesc const& a : layoutDesc(renderer_->layout()).attachments())
        for (char const* ext : {".exr", ".png"})
            EXPECT_FALSE(std::filesystem::exists(dir + "/raw_" + std::string(a.name) + ext)) << a.name;
    auto const raw = readImage(dir + "/raw_prepass_normal_exp.exr");
    ASSERT_TRUE(raw);
    EXPECT_EQ(raw->pixels, renderer_->readAttachment(Attachment::PrepassNormal).pixels);
    auto const normal = readImage(dir + "/normal.exr");
    ASSERT_TRUE(normal);
    EXPECT_EQ(normal->pixels, renderer_->readAttachment(Attachment::Normal).pixels);
    auto const exponent = readImage(dir + "/specular_exponent.exr");
    ASSERT_TRUE(exponent);
    ASSERT_EQ(exponent->channels, 1);
    EXPECT_EQ(exponent->at(kW / 2, kH - 10, 0), settings_.shininess);
    std::ifstream stats(dir + "/stats.json");
    nlohmann::json const j = nlohmann::json::parse(stats);
    EXPECT_EQ(j.value("gbuffer_note", ""), kPrepassExportNote);
}

}  // namespace
