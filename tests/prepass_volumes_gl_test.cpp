// prepass with `prepass_lights: volumes`: its light pass draws the light volumes with each cull mode,
// each volume adding its light's diffuse and specular light, and equals the full-screen light pass
// (and quad) within the lighting modes' bound, from above and from inside a light's volume; the
// cull modes that are wrong on purpose are wrong by the amount they should be. And the triangles each
// pass draws: prepass's two geometry passes draw the scene's, and the frame's total is the passes'.
#include "core/light_math.h"
#include "core/light_volume_cone.h"
#include "core/light_volume_mesh.h"
#include "lighting_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

using namespace gbl;

namespace {

constexpr int kW = 160, kH = 90;

// `image` against `reference` within forward's bound (lighting_compare.h: prepass, like forward, is held to
// quad by it): visibly lit (mean over `minMean`), mean error under 1 % of the mean value, and under 0.5 % of
// the pixels over the bound.
void expectWithinBound(FloatImage const& image, FloatImage const& reference, std::string const& what,
                       double minMean = 0.01) {
    test::ImageDiff const d = test::compareRgb(image, reference, test::forwardBound);
    std::printf("%s: %s\n", what.c_str(), test::describe(d).c_str());
    EXPECT_GT(d.meanValue, minMean) << what << ": the frame should be visibly lit";
    EXPECT_LT(d.meanAbs, 0.01 * d.meanValue) << what << ": " << test::describe(d);
    EXPECT_LT(d.pixelsOver, reference.width * reference.height / 200) << what << ": " << test::describe(d);
}

double meanOf(FloatImage const& img) {
    double sum = 0.0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            for (int c = 0; c < 3; ++c) sum += img.at(x, y, c);
    return sum / (double(img.width) * img.height * 3);
}

// What a frame left in the lit image and the two light targets.
struct Lit {
    FloatImage lighting, diffuse, specular;
    FrameStats stats;
};

class PrepassVolumesGlTest : public test::LightingGlTest {
protected:
    PrepassVolumesGlTest() : LightingGlTest(kW, kH) {}

    void SetUp() override {
        LightingGlTest::SetUp();
        if (IsSkipped() || HasFatalFailure()) return;
        // A spot (its cone volume) and a directional light (no volume: the full-screen group) beside the
        // scene's point lights; the camera above stays outside every volume (radii up to 7.5, 3 up).
        PointLight& spot = lights_[1];
        spot.kind = LightKind::Spot;
        spot.direction = {0.3f, -1.0f, 0.1f};
        spot.innerConeDeg = 20.0f;
        spot.outerConeDeg = 35.0f;
        PointLight sun;
        sun.kind = LightKind::Directional;
        sun.direction = {-0.4f, -1.0f, -0.3f};
        sun.color = {0.3f, 0.35f, 0.4f};
        sun.intensity = 0.3f;
        withSun_ = lights_;
        withSun_.push_back(sun);
    }

    Lit render(LightingMode mode, PrepassLights lightPass, CullMode cull, Camera const& cam,
               std::vector<PointLight> const& lights) {
        PipelineSettings s;
        s.mode = mode;
        s.prepassLights = lightPass;
        s.cull = cull;
        s.lightCubes = false;  // the lighting alone
        Lit out;
        out.stats = renderer_->render({cam, lights, s, true});
        EXPECT_EQ(out.stats.modeUsed, mode) << out.stats.fallbackReason;
        EXPECT_EQ(out.stats.fallbackReason, "");
        EXPECT_EQ(out.stats.glErrors, 0u);
        out.lighting = renderer_->readAttachment(Attachment::Lighting);
        out.diffuse = renderer_->readAttachment(Attachment::DiffuseLight);
        out.specular = renderer_->readAttachment(Attachment::SpecularLight);
        return out;
    }
    Lit prepass(PrepassLights lightPass, CullMode cull, Camera const& cam) {
        return render(LightingMode::Prepass, lightPass, cull, cam, withSun_);
    }

    // The volumes with `cull` against the full-screen light pass: the light targets and the lit image,
    // and the lit image against quad's.
    void expectMatchesFullScreen(CullMode cull, Camera const& cam, std::string const& where) {
        std::string const what = std::string(kCullModeNames[std::size_t(cull)]) + ", " + where;
        Lit const quadPass = prepass(PrepassLights::Quad, cull, cam);
        Lit const volumes = prepass(PrepassLights::Volumes, cull, cam);
        EXPECT_GT(test::passCalls(volumes.stats, "lighting").draws, 1u) << what << ": the volumes were drawn";
        expectWithinBound(volumes.diffuse, quadPass.diffuse, "diffuse light, " + what);
        // Specular light is small beside diffuse from above (highlights cover few pixels): 0.0086 on average.
        expectWithinBound(volumes.specular, quadPass.specular, "specular light, " + what, 0.004);
        expectWithinBound(volumes.lighting, quadPass.lighting, "lit image, " + what);
        Lit const quad = render(LightingMode::Quad, PrepassLights::Quad, cull, cam, withSun_);
        expectWithinBound(volumes.lighting, quad.lighting, "lit image against quad, " + what);
    }

    std::vector<PointLight> withSun_;  // lights_ and a directional light
};

}  // namespace

TEST_F(PrepassVolumesGlTest, EveryCullModeThatHoldsMatchesTheFullScreenLightPassFromAbove) {
    for (CullMode cull : {CullMode::Back, CullMode::Front, CullMode::Flip, CullMode::Stencil})
        expectMatchesFullScreen(cull, camera_, "test camera");
}

TEST_F(PrepassVolumesGlTest, TheCullModesForTheCameraInsideMatchFromInsideAVolume) {
    Camera const inside = insideCamera();
    ASSERT_LT(glm::length(inside.position - lights_[0].position), lightRadius(lights_[0]).radius);
    for (CullMode cull : {CullMode::Front, CullMode::Flip, CullMode::Stencil})
        expectMatchesFullScreen(cull, inside, "inside light 0");
}

// The two cull modes kept as visible bugs are wrong by their amount: `none` draws both faces with no
// depth test, so every pixel under a volume gets its light twice (no directional light here: it has
// no volume); `back` loses the lights whose volume holds the camera (their front faces are behind it),
// light 0's and any other's around it, and never adds light the full-screen pass lacks.
TEST_F(PrepassVolumesGlTest, NoneAddsEachLightTwiceAndBackLosesTheLightAroundTheCamera) {
    Lit const once = render(LightingMode::Prepass, PrepassLights::Quad, CullMode::None, camera_, lights_);
    Lit const none = render(LightingMode::Prepass, PrepassLights::Volumes, CullMode::None, camera_, lights_);
    FloatImage twice = once.diffuse;
    for (float& v : twice.pixels) v *= 2.0f;
    expectWithinBound(none.diffuse, twice, "none's diffuse light against twice the full-screen pass's");

    Camera const inside = insideCamera();
    Lit const all = render(LightingMode::Prepass, PrepassLights::Quad, CullMode::Back, inside, lights_);
    Lit const back = render(LightingMode::Prepass, PrepassLights::Volumes, CullMode::Back, inside, lights_);
    std::vector<PointLight> withoutLight0(lights_.begin() + 1, lights_.end());
    Lit const missing = render(LightingMode::Prepass, PrepassLights::Quad, CullMode::Back, inside, withoutLight0);
    ASSERT_GT(meanOf(all.diffuse), 1.2 * meanOf(missing.diffuse)) << "light 0 should light much of this view";
    EXPECT_LE(meanOf(back.diffuse), meanOf(missing.diffuse) * 1.01) << "back should lose at least light 0";
    int brighter = 0;  // pixels where back added more than the full-screen pass's every light (fp16 aside)
    for (std::size_t i = 0; i < back.diffuse.pixels.size(); ++i)
        brighter += back.diffuse.pixels[i] > all.diffuse.pixels[i] * 1.03f + 2e-3f;
    EXPECT_EQ(brighter, 0);
}

// The light pass (its declaration: frame_passes_prepass_test) runs after a blit of the thin depth:
// one full-screen draw for the directional lights, then the volumes' instanced draws, and its
// triangles are the full-screen one and every light's volume mesh.
TEST_F(PrepassVolumesGlTest, TheLightPassDrawsTheDirectionalLightsThenEachVolumeMesh) {
    Lit const lit = prepass(PrepassLights::Volumes, CullMode::Flip, camera_);
    EXPECT_EQ(test::passCalls(lit.stats, "volume_depth").draws, 0u);  // a blit
    // The full-screen draw, then the sphere mesh's and the cone mesh's instanced draws (all outside).
    EXPECT_EQ(test::passCalls(lit.stats, "lighting").draws, 3u);
    Lit const full = prepass(PrepassLights::Quad, CullMode::Flip, camera_);
    EXPECT_EQ(test::passCalls(full.stats, "lighting").draws, 1u);
    EXPECT_EQ(test::passCalls(full.stats, "lighting").triangles, 1u);  // one full-screen triangle
    // Its triangles: the full-screen one and each light's volume mesh (core/light_volume_*.h).
    std::uint64_t volumes = 1;
    for (PointLight const& l : withSun_) {
        if (lightRadius(l).radius <= 0.0f) continue;
        if (volumeShape(l) == VolumeShape::Sphere) volumes += makeLightVolumeSphere().triangles.size() / 3;
        if (volumeShape(l) == VolumeShape::Cone) volumes += makeLightVolumeCone().triangles.size() / 3;
    }
    EXPECT_GT(volumes, 1u + lights_.size() * 10u);
    EXPECT_EQ(test::passCalls(lit.stats, "lighting").triangles, volumes);
}

// Triangles per pass (gl/draw_count.h): prepass's two geometry passes each draw the scene's
// triangles (the default scene is opaque), quad's geometry pass the same, and a frame's total is its
// passes' sum.
TEST_F(PrepassVolumesGlTest, EachGeometryPassDrawsTheScenesTrianglesAndTheTotalIsTheirSum) {
    std::uint64_t const scene = scene_.triangleCount();
    ASSERT_GT(scene, 0u);
    Lit const pre = prepass(PrepassLights::Quad, CullMode::Front, camera_);
    EXPECT_EQ(test::passCalls(pre.stats, "prepass_geometry").triangles, scene);
    EXPECT_EQ(test::passCalls(pre.stats, "prepass_shading").triangles, scene);
    EXPECT_EQ(test::passCalls(pre.stats, "forward").triangles, 0u);  // no blended surface
    Lit const quad = render(LightingMode::Quad, PrepassLights::Quad, CullMode::Front, camera_, withSun_);
    EXPECT_EQ(test::passCalls(quad.stats, "geometry").triangles, scene);
    for (FrameStats const* st : {&pre.stats, &quad.stats}) {
        std::uint64_t sum = 0, draws = 0;
        for (PassCalls const& c : st->calls) sum += c.triangles, draws += c.draws;
        EXPECT_EQ(st->triangles(), sum);
        EXPECT_EQ(st->draws(), draws);
    }
    // The scene twice and two full-screen triangles (the light pass and the display), against once
    // and two (the lighting and the display): prepass draws the scene's triangles twice.
    EXPECT_EQ(pre.stats.triangles(), 2 * scene + 2);
    EXPECT_EQ(quad.stats.triangles(), scene + 2);
}
