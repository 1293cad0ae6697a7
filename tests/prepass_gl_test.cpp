// prepass (deferred lighting: a thin G-buffer, the lights summed into diffuse and specular light,
// the scene drawn again applying its materials) against the CPU shading and against quad, from the
// test camera, the scene's camera and a camera inside a light's volume; its declared passes run in
// order and its second geometry pass draws what its first drew.
#include "core/light_math.h"
#include "core/shading_cpu.h"
#include "gl_fixture.h"
#include "test_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

using namespace gbl;

namespace {

constexpr int kW = 160, kH = 90;

struct Diff {
    double maxAbs = 0.0;
    double meanAbs = 0.0;
    double meanValue = 0.0;
    int pixelsOver = 0;
};

// Against quad: prepass reads its material from the scene, not from the G-buffer (albedo and
// specular in 8 bits there, 1/510 at worst), rebuilds position from the depth where classic reads it
// in fp16 (1/64 unit at 16..32 units), and stores the two light sums in fp16 before the material
// multiplies them. Those are the differences forward has from quad, and the same bound as forward's
// (light_modes_gl_test): 3 % of the value + 2e-3 at 99.5 % of the pixels, a mean error under 1 % of
// the mean value.
Diff compare(FloatImage const& a, FloatImage const& ref) {
    Diff d;
    EXPECT_EQ(a.width, ref.width);
    EXPECT_EQ(a.height, ref.height);
    double sumErr = 0.0, sum = 0.0;
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) {
            bool over = false;
            for (int c = 0; c < 3; ++c) {
                double const va = a.at(x, y, c), vr = ref.at(x, y, c);
                double const e = std::abs(va - vr);
                d.maxAbs = std::max(d.maxAbs, e);
                sumErr += e;
                sum += std::abs(vr);
                if (e > 0.03 * std::abs(vr) + 2e-3) over = true;
            }
            d.pixelsOver += over;
        }
    double const n = double(ref.width) * ref.height * 3;
    d.meanAbs = sumErr / n;
    d.meanValue = sum / n;
    return d;
}

std::string describe(Diff const& d) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "max abs %.3g, mean abs %.3g (mean value %.3g), pixels over bound %d", d.maxAbs,
                  d.meanAbs, d.meanValue, d.pixelsOver);
    return buf;
}

PipelineSettings settingsFor(LightingMode mode) {
    PipelineSettings s;
    s.mode = mode;
    s.lightCubes = false;  // the lighting alone
    return s;
}

PassCalls callsOf(FrameStats const& st, std::string const& name) {
    auto const it = std::find_if(st.calls.begin(), st.calls.end(), [&](PassCalls const& c) { return c.name == name; });
    return it == st.calls.end() ? PassCalls{} : *it;
}

class PrepassGlTest : public test::CourtyardGlTest {
protected:
    PrepassGlTest() : CourtyardGlTest(kW, kH) {}

    FloatImage lighting(PipelineSettings const& s, Camera const& cam, FrameStats* out = nullptr) {
        FrameStats const st = renderer_->render({cam, lights_, s, true});
        EXPECT_EQ(st.modeUsed, s.mode) << st.fallbackReason;
        EXPECT_EQ(st.glErrors, 0u);
        if (out) *out = st;
        return renderer_->readAttachment(Attachment::Lighting);
    }

    void expectMatchesQuad(Camera const& cam, std::string const& where) {
        FloatImage const quad = lighting(settingsFor(LightingMode::Quad), cam);
        FloatImage const prepass = lighting(settingsFor(LightingMode::Prepass), cam);
        Diff const d = compare(prepass, quad);
        std::printf("prepass against quad, %s: %s\n", where.c_str(), describe(d).c_str());
        EXPECT_GT(d.meanValue, 0.01) << where << ": the frame should be visibly lit";
        EXPECT_LT(d.meanAbs, 0.01 * d.meanValue) << where << ": " << describe(d);
        EXPECT_LT(d.pixelsOver, kW * kH / 200) << where << ": " << describe(d);
    }

    // Camera inside light 0's sphere, looking at the floor under it (as light_modes_gl_test's).
    Camera insideCamera() const {
        PointLight const& l = lights_[0];
        Camera c = camera_;
        c.position = l.position + glm::vec3(0.3f, 0.4f, 0.3f);
        c.lookAt(glm::vec3(l.position.x, 0.0f, l.position.z) + glm::vec3(0.0f, 0.0f, -2.0f));
        return c;
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
    lighting(settingsFor(LightingMode::Prepass), camera_, &st);
    std::vector<std::string> ran;
    for (PassCalls const& c : st.calls) ran.push_back(c.name);
    EXPECT_EQ(ran, (std::vector<std::string>{"prepass_geometry", "lighting", "prepass_shading", "forward", "display"}));
    // The opaque scene drawn once into the thin G-buffer and once applying the materials, the
    // lights summed by one full-screen draw in between.
    EXPECT_GT(callsOf(st, "prepass_geometry").draws, 0u);
    EXPECT_EQ(callsOf(st, "prepass_geometry").draws, callsOf(st, "prepass_shading").draws);
    EXPECT_EQ(callsOf(st, "lighting").draws, 1u);
    // The quad frame draws the opaque scene once: the G-buffer's draws are prepass's first pass's.
    FrameStats quad;
    lighting(settingsFor(LightingMode::Quad), camera_, &quad);
    EXPECT_EQ(callsOf(quad, "geometry").draws, callsOf(st, "prepass_geometry").draws);
}

TEST_F(PrepassGlTest, RefusesSplitAccumulationAndMsaaWithAReason) {
    PipelineSettings s = settingsFor(LightingMode::Prepass);
    s.accumulation = LightAccumulation::Split;
    FrameStats st = renderer_->render({camera_, lights_, s, true});
    EXPECT_EQ(st.modeUsed, LightingMode::Prepass);
    EXPECT_EQ(st.accumulationUsed, LightAccumulation::Single);
    EXPECT_NE(st.fallbackReason.find("prepass always sums its lights"), std::string::npos) << st.fallbackReason;
    s = settingsFor(LightingMode::Prepass);
    s.msaa = Msaa::X4;
    st = renderer_->render({camera_, lights_, s, true});
    EXPECT_EQ(st.modeUsed, LightingMode::Prepass);
    EXPECT_EQ(st.msaaUsed, Msaa::Off);
    EXPECT_NE(st.fallbackReason.find("this frame ran prepass mode"), std::string::npos) << st.fallbackReason;
    EXPECT_EQ(st.glErrors, 0u);
}

class PrepassFloorGlTest : public test::GlTest {};

// The floor (y = 0, normal +Y, the plane's albedo and specular) under one light: each pixel's lit
// value is the CPU's Blinn-Phong at the point its ray meets the floor.
TEST_F(PrepassFloorGlTest, MatchesTheCpuShadingOnTheFloor) {
    int const w = 64, h = 64;
    auto r = makeRenderer(w, h);
    ASSERT_FALSE(r->setScene(test::floorScene()));
    Camera const cam = test::lookingAt({0.0f, 8.0f, 6.0f}, {0.0f, 0.0f, 0.0f});
    PointLight light;
    light.position = {2.5f, 1.0f, 0.0f};
    light.color = {1.0f, 0.8f, 0.6f};
    light.intensity = 1.5f;
    light.kc = 1.0f;
    light.kl = 0.7f;
    light.kq = 1.8f;  // radius ~6.2: part of the visible floor is lit, part lies beyond
    std::vector<PointLight> const lights{light};
    PipelineSettings s = settingsFor(LightingMode::Prepass);
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
