// prepass (deferred lighting: a thin G-buffer, the lights summed into diffuse and specular light,
// the scene drawn again applying its materials) against the CPU shading and against quad, from the
// test camera, the scene's camera and a camera inside a light's volume; its declared passes run in
// order and its second geometry pass draws what its first drew.
#include "core/light_math.h"
#include "core/shading_cpu.h"
#include "lighting_compare.h"
#include "test_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

using namespace gbl;
using namespace gbl::test;

namespace {

constexpr int kW = 160, kH = 90;

class PrepassGlTest : public LightingGlTest {
protected:
    PrepassGlTest() : LightingGlTest(kW, kH) {}

    void expectMatchesQuad(Camera const& cam, std::string const& where) {
        FloatImage const quad = lighting(lightingSettings(LightingMode::Quad), cam);
        FloatImage const prepass = lighting(lightingSettings(LightingMode::Prepass), cam);
        // Prepass reads its material from the scene, not from the G-buffer, rebuilds position from the
        // depth where quad reads it in fp16, and stores the two light sums in fp16 before the material
        // multiplies them: the differences forward has from quad, and forward's bound (light_modes_gl_test):
        // 99.5 % of the pixels within forwardBound, a mean error under 1 % of the mean value.
        ImageDiff const d = compareRgb(prepass, quad, forwardBound);
        std::printf("prepass against quad, %s: %s\n", where.c_str(), describe(d).c_str());
        EXPECT_GT(d.meanValue, 0.01) << where << ": the frame should be visibly lit";
        EXPECT_LT(d.meanAbs, 0.01 * d.meanValue) << where << ": " << describe(d);
        EXPECT_LT(d.pixelsOver, kW * kH / 200) << where << ": " << describe(d);
    }
};

}  // namespace

TEST_F(PrepassGlTest, MatchesQuadFromTheTestCamera) {
    expectMatchesQuad(camera_, "test camera");
}

TEST_F(PrepassGlTest, MatchesQuadFromTheDefaultSceneCamera) {
    expectMatchesQuad(scene_.camera.value_or(Camera{}), "scene camera");
}

TEST_F(PrepassGlTest, MatchesQuadWithTheCameraInsideAVolume) {
    Camera const cam = insideCamera();
    ASSERT_LT(glm::length(cam.position - lights_[0].position), lightRadius(lights_[0]).radius);
    expectMatchesQuad(cam, "inside light 0");
}

TEST_F(PrepassGlTest, RunsItsDeclaredPassesInOrderAndDrawsTheSceneTwice) {
    FrameStats st;
    lighting(lightingSettings(LightingMode::Prepass), camera_, lights_, &st);
    std::vector<std::string> ran;
    for (PassCalls const& c : st.calls) ran.push_back(c.name);
    EXPECT_EQ(ran, (std::vector<std::string>{"prepass_geometry", "lighting", "prepass_shading", "forward", "display"}));
    // The opaque scene drawn once into the thin G-buffer and once applying the materials, the
    // lights summed by one full-screen draw in between.
    EXPECT_GT(passCalls(st, "prepass_geometry").draws, 0u);
    EXPECT_EQ(passCalls(st, "prepass_geometry").draws, passCalls(st, "prepass_shading").draws);
    EXPECT_EQ(passCalls(st, "lighting").draws, 1u);
    // The quad frame draws the opaque scene once: the G-buffer's draws are prepass's first pass's.
    FrameStats quad;
    lighting(lightingSettings(LightingMode::Quad), camera_, lights_, &quad);
    EXPECT_EQ(passCalls(quad, "geometry").draws, passCalls(st, "prepass_geometry").draws);
}

TEST_F(PrepassGlTest, RefusesSplitAccumulationAndMsaaWithAReason) {
    PipelineSettings s = lightingSettings(LightingMode::Prepass);
    s.accumulation = LightAccumulation::Split;
    FrameStats st = renderer_->render({camera_, lights_, s, true});
    EXPECT_EQ(st.modeUsed, LightingMode::Prepass);
    EXPECT_EQ(st.accumulationUsed, LightAccumulation::Single);
    EXPECT_NE(st.fallbackReason.find("prepass always sums its lights"), std::string::npos) << st.fallbackReason;
    s = lightingSettings(LightingMode::Prepass);
    s.msaa = Msaa::X4;
    st = renderer_->render({camera_, lights_, s, true});
    EXPECT_EQ(st.modeUsed, LightingMode::Prepass);
    EXPECT_EQ(st.msaaUsed, Msaa::Off);
    EXPECT_NE(st.fallbackReason.find("this frame ran prepass mode"), std::string::npos) << st.fallbackReason;
    EXPECT_EQ(st.glErrors, 0u);
}

class PrepassFloorGlTest : public GlTest {};

// The floor (y = 0, normal +Y, the plane's albedo and specular) under one light: each pixel's lit
// value is the CPU's Blinn-Phong at the point its ray meets the floor.
TEST_F(PrepassFloorGlTest, MatchesTheCpuShadingOnTheFloor) {
    int const w = 64, h = 64;
    auto r = makeRenderer(w, h);
    ASSERT_FALSE(r->setScene(test::floorScene()));
    Camera const cam = test::lookingAt({0.0f, 8.0f, 6.0f}, {0.0f, 0.0f, 0.0f});
    PointLight const light = test::floorTestLight();
    std::vector<PointLight> const lights{light};
    PipelineSettings s = lightingSettings(LightingMode::Prepass);
    s.ambient = glm::vec3(0.03f);
    FrameStats const st = r->render({cam, lights, s});
    ASSERT_EQ(st.modeUsed, LightingMode::Prepass) << st.fallbackReason;
    FloatImage const lit = r->readAttachment(Attachment::Lighting);
    FloatImage const diffuse = r->readAttachment(Attachment::DiffuseLight);
    float const radius = lightRadius(light).radius;
    double sumErr = 0.0;
    int litPixels = 0, darkPixels = 0, covered = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            test::Ray const ray = test::pixelRay(cam, w, h, x, y);
            if (ray.dir.y >= 0.0f) continue;  // the sky: the floor is below the camera
            ++covered;
            ShadingInputs in;
            in.position = ray.origin + ray.dir * (-ray.origin.y / ray.dir.y);
            in.normal = {0.0f, 1.0f, 0.0f};
            in.albedo = test::kPlaneAlbedo;
            in.specular = test::kPlaneSpecular;
            in.viewPosition = cam.position;
            in.shininess = s.shininess;
            glm::vec3 const expected = shadePointCpu(lights, in, s.ambient);
            bool const reached = glm::length(light.position - in.position) < radius;
            (reached ? litPixels : darkPixels)++;
            // The light target holds light alone: N.L * attenuation * colour, no albedo.
            if (!reached) {
                EXPECT_EQ(diffuse.at(x, y, 0), 0.0f) << "pixel " << x << "," << y;
            }
            for (int c = 0; c < 3; ++c) {
                // Two fp16 stores (the light sum, then the lit value): 2 x 2^-11 relative, plus the
                // position rebuilt from a 32-bit float depth and pow() on GPU and CPU: 3e-3 relative.
                double const err = std::abs(double(lit.at(x, y, c)) - expected[c]);
                EXPECT_LE(err, 3e-3 * std::max(1.0, double(std::abs(expected[c])))) << "pixel " << x << "," << y;
                sumErr += err;
            }
        }
    ASSERT_GT(covered, 0);
    EXPECT_GT(litPixels, 50) << "the light should reach part of the floor";
    EXPECT_GT(darkPixels, 50) << "part of the floor should lie beyond the radius";
    // Mean error well below the per-pixel bound: a systematic offset would show here.
    EXPECT_LT(sumErr / (covered * 3), 3e-4);
}
