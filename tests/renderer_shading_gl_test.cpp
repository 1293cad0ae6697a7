// The deferred core's pixels on a headless context: G-buffer contents against analytic values, the
// lighting pass against the CPU equation, the depth copy hiding a light cube behind a wall, and the
// overlays drawn on the display image. Resizing, reloads, timings and stops: renderer_gl_test.
#include "core/shading_cpu.h"
#include "gl_fixture.h"
#include "test_scenes.h"

using namespace gbl;
using gbl::test::GlTest;

namespace {

using test::lookingAt;
using test::pixelRay;
using test::plainSettings;
using test::Ray;

}  // namespace

class RendererGlTest : public GlTest {};

TEST_F(RendererGlTest, FloorFillsGBufferWithAnalyticValues) {
    int const w = 64, h = 48;
    auto r = makeRenderer(w, h);
    ASSERT_FALSE(r->setScene(test::floorScene()));
    Camera const cam = lookingAt({0.0f, 5.0f, 5.0f}, {0.0f, 0.0f, 0.0f});
    r->render({cam, {}, plainSettings()});

    FloatImage const pos = r->readAttachment(Attachment::Position);
    FloatImage const nrm = r->readAttachment(Attachment::Normal);
    FloatImage const alb = r->readAttachment(Attachment::AlbedoSpec);
    FloatImage const dep = r->readAttachment(Attachment::Depth);
    glm::mat4 const viewProj = cam.projection(float(w) / float(h)) * cam.view();
    int covered = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            Ray const ray = pixelRay(cam, w, h, x, y);
            bool const hits = ray.dir.y < 0.0f;
            float const t = hits ? -ray.origin.y / ray.dir.y : 0.0f;
            glm::vec3 const hit = ray.origin + ray.dir * t;
            bool const onFloor = hits && std::abs(hit.x) < 20.0f && std::abs(hit.z) < 20.0f && t < cam.farPlane;
            ASSERT_EQ(pos.at(x, y, 3) > 0.5f, onFloor) << "coverage at " << x << "," << y;
            if (!onFloor) {
                EXPECT_EQ(nrm.at(x, y, 0), 0.0f) << "background must stay cleared to black";
                continue;
            }
            ++covered;
            // A floor facing +Y stores exactly (0, 1, 0): 0 and 1 are exact in half floats.
            EXPECT_EQ(nrm.at(x, y, 0), 0.0f);
            EXPECT_EQ(nrm.at(x, y, 1), 1.0f);
            EXPECT_EQ(nrm.at(x, y, 2), 0.0f);
            // Position: half floats keep 11 significant bits, so |v| < 32 rounds by at most
            // 32 * 2^-11 = 0.016; rasterisation samples the pixel centre like the ray does.
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(pos.at(x, y, c), hit[c], 0.016f) << "position at " << x << "," << y;
            // Albedo and specular are 8-bit: one step of 1/255.
            EXPECT_NEAR(alb.at(x, y, 0), test::kPlaneAlbedo.r, 1.0f / 255.0f);
            EXPECT_NEAR(alb.at(x, y, 1), test::kPlaneAlbedo.g, 1.0f / 255.0f);
            EXPECT_NEAR(alb.at(x, y, 2), test::kPlaneAlbedo.b, 1.0f / 255.0f);
            EXPECT_NEAR(alb.at(x, y, 3), test::kPlaneSpecular, 1.0f / 255.0f);
            // Depth: the projected hit point in window space; a 32-bit float depth buffer
            // agrees to about 1e-6 (interpolation of z/w across the triangle).
            glm::vec4 const clip = viewProj * glm::vec4(hit, 1.0f);
            EXPECT_NEAR(dep.at(x, y, 0), clip.z / clip.w * 0.5f + 0.5f, 2e-6f) << "depth at " << x << "," << y;
        }
    }
    EXPECT_GT(covered, w * h / 3) << "the floor should cover a good part of the frame";
}

TEST_F(RendererGlTest, WorldPositionRebuiltFromDepthMatchesStoredPosition) {
    int const w = 48, h = 48;
    auto r = makeRenderer(w, h);
    ASSERT_FALSE(r->setScene(test::floorAndWallScene()));
    Camera const cam = lookingAt({3.0f, 4.0f, 7.0f}, {0.0f, 1.0f, 0.0f});
    r->render({cam, {}, plainSettings()});
    int checked = 0;
    for (int y = 0; y < h; y += 5)
        for (int x = 0; x < w; x += 5) {
            PixelSample const s = r->samplePixel(x, y, cam);
            if (!s.covered) continue;
            ++checked;
            // Stored positions are half floats: rounding up to 2^-11 |v|; interpolation and the
            // float depth add about as much again, so allow 1e-3 |v| plus a small floor.
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(s.reconstructedPosition[c], s.position[c], 1e-3f * std::abs(s.position[c]) + 4e-3f);
        }
    EXPECT_GT(checked, 20);
}

TEST_F(RendererGlTest, LightingPassMatchesCpuEquation) {
    int const w = 64, h = 64;
    auto r = makeRenderer(w, h);
    ASSERT_FALSE(r->setScene(test::floorScene()));
    Camera const cam = lookingAt({0.0f, 8.0f, 6.0f}, {0.0f, 0.0f, 0.0f});
    PointLight const light = test::floorTestLight();
    std::vector<PointLight> const lights{light};
    PipelineSettings const settings = plainSettings();
    r->render({cam, lights, settings});

    FloatImage const pos = r->readAttachment(Attachment::Position);
    FloatImage const nrm = r->readAttachment(Attachment::Normal);
    FloatImage const alb = r->readAttachment(Attachment::AlbedoSpec);
    FloatImage const lit = r->readAttachment(Attachment::Lighting);
    float const radius = lightRadius(light).radius;
    double sumErr = 0.0, maxErr = 0.0;
    int litPixels = 0, darkPixels = 0, covered = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (pos.at(x, y, 3) == 0.0f) continue;
            ++covered;
            // Shade from the stored G-buffer values, as the GPU does, so only the equation and
            // the HDR target's precision are compared.
            ShadingInputs in;
            in.position = {pos.at(x, y, 0), pos.at(x, y, 1), pos.at(x, y, 2)};
            in.normal = glm::normalize(glm::vec3(nrm.at(x, y, 0), nrm.at(x, y, 1), nrm.at(x, y, 2)));
            in.albedo = {alb.at(x, y, 0), alb.at(x, y, 1), alb.at(x, y, 2)};
            in.specular = alb.at(x, y, 3);
            in.viewPosition = cam.position;
            in.shininess = settings.shininess;
            glm::vec3 const expected = shadePointCpu(lights, in, settings.ambient);
            bool const reached = glm::length(light.position - in.position) < radius;
            (reached ? litPixels : darkPixels)++;
            for (int c = 0; c < 3; ++c) {
                // RGBA16F stores 11 significant bits: relative error 2^-11 ~ 4.9e-4, plus float
                // differences in pow() between GPU and CPU; 2e-3 relative bounds both.
                double const err = std::abs(double(lit.at(x, y, c)) - expected[c]);
                double const allowed = 2e-3 * std::max(1.0, double(std::abs(expected[c])));
                EXPECT_LE(err, allowed) << "pixel " << x << "," << y << " channel " << c;
                maxErr = std::max(maxErr, err);
                sumErr += err;
            }
        }
    ASSERT_GT(covered, 0);
    EXPECT_GT(litPixels, 50) << "the light should reach part of the floor";
    EXPECT_GT(darkPixels, 50) << "part of the floor should lie beyond the radius";
    // Mean error well below the per-pixel bound: a systematic offset would show here.
    EXPECT_LT(sumErr / (covered * 3), 3e-4);
}

TEST_F(RendererGlTest, PixelsBeyondRadiusGetOnlyAmbient) {
    int const w = 32, h = 32;
    auto r = makeRenderer(w, h);
    ASSERT_FALSE(r->setScene(test::floorScene()));
    Camera const cam = lookingAt({0.0f, 3.0f, 3.0f}, {0.0f, 0.0f, 0.0f});
    PointLight light;
    light.position = {0.0f, 0.5f, -15.0f};  // radius ~5: nowhere near what the camera sees
    std::vector<PointLight> const lights{light};
    PipelineSettings const settings = plainSettings();
    r->render({cam, lights, settings});
    FloatImage const alb = r->readAttachment(Attachment::AlbedoSpec);
    FloatImage const lit = r->readAttachment(Attachment::Lighting);
    PixelSample const centre = r->samplePixel(w / 2, h / 2, cam);
    ASSERT_TRUE(centre.covered);
    ASSERT_GT(glm::length(light.position - glm::vec3(centre.position)), lightRadius(light).radius);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(lit.at(w / 2, h / 2, c), settings.ambient[c] * alb.at(w / 2, h / 2, c), 1e-4f);
}

namespace {
// Where a world point projects, in pixels (y from the top).
glm::ivec2 projectedPixel(Renderer const& r, Camera const& cam, glm::vec3 p) {
    glm::vec4 const clip = cam.projection(float(r.width()) / float(r.height())) * cam.view() * glm::vec4(p, 1.0f);
    glm::vec3 const ndc = glm::vec3(clip) / clip.w;
    return {int((ndc.x * 0.5f + 0.5f) * float(r.width())), int((0.5f - ndc.y * 0.5f) * float(r.height()))};
}

glm::vec3 rgbAt(FloatImage const& img, glm::ivec2 px) {
    return {img.at(px.x, px.y, 0), img.at(px.x, px.y, 1), img.at(px.x, px.y, 2)};
}

// The display's default tonemap (`exposure`, exposure 1) on the CPU: pow(1 - exp(-x), 1/2.2), as
// shaders/tonemap.glsl computes it (docs/lighting.md, Tonemap and display).
glm::vec3 tonemapExposure(glm::vec3 hdr) {
    return glm::pow(glm::vec3(1.0f) - glm::exp(-hdr), glm::vec3(1.0f / 2.2f));
}

// The display image (0..1) at the pixel where the light's centre projects, after a frame with
// light cubes on: the cubes are an overlay on the display, not part of the lit image.
glm::vec3 cubePixel(Renderer& r, Camera const& cam, PointLight const& light, DepthCopy copy) {
    PipelineSettings s = plainSettings();
    s.lightCubes = true;
    s.depthCopy = copy;
    std::vector<PointLight> const lights{light};
    r.render({cam, lights, s});
    return rgbAt(r.readAttachment(Attachment::Final), projectedPixel(r, cam, light.position));
}
}  // namespace

TEST_F(RendererGlTest, BlitStepHidesLightCubeBehindWall) {
    auto r = makeRenderer(96, 64);
    ASSERT_FALSE(r->setScene(test::floorAndWallScene()));
    Camera const cam = lookingAt({0.0f, 2.0f, 6.0f}, {0.0f, 2.0f, 0.0f});
    PointLight light;
    light.position = {0.0f, 2.0f, -2.0f};  // behind the wall (front face at z = 0)
    light.color = {0.0f, 1.0f, 0.0f};
    // The cube is emissive: colour x kLightCubeEmissive in HDR, unlit, tonemapped as the lit image
    // is: (0, 0.88, 0) on the display. The wall (lit by the ambient term only) is nowhere near that
    // green.
    glm::vec3 const cube = tonemapExposure(light.color * kLightCubeEmissive);
    glm::vec3 const off = cubePixel(*r, cam, light, DepthCopy::Off);
    glm::vec3 const blit = cubePixel(*r, cam, light, DepthCopy::Blit);
    glm::vec3 const shader = cubePixel(*r, cam, light, DepthCopy::Shader);
    // RGBA8 display: one step (1/255) of rounding per channel, plus one for GPU exp/pow against the CPU's.
    EXPECT_NEAR(glm::length(off - cube), 0.0f, 2.0f / 255.0f)
        << "without the blit step the cube shows through the wall";
    EXPECT_GT(glm::length(blit - cube), 0.5f) << "with glBlitFramebuffer the wall hides the cube";
    EXPECT_GT(glm::length(shader - cube), 0.5f) << "with the shader copy the wall hides the cube";
    EXPECT_NEAR(glm::length(blit - shader), 0.0f, 1e-3f) << "both copies give the same depth";
}

TEST_F(RendererGlTest, OverlaysDrawOnTheDisplayAndLeaveTheLitImageAlone) {
    // Issue 24: the light cubes and the volume wireframes are drawn onto the display image after the
    // display pass, so toggling them changes the display where they are drawn and never the lit image
    // (the light sum that lighting.exr exports); the G-buffer views show none of them.
    auto r = makeRenderer(96, 64);
    ASSERT_FALSE(r->setScene(test::floorScene()));
    Camera const cam = lookingAt({0.0f, 3.0f, 5.0f}, {0.0f, 0.0f, 0.0f});
    PointLight light;
    light.position = {0.0f, 0.5f, 0.0f};  // above the floor, its cube and sphere in view
    light.color = {1.0f, 0.5f, 0.0f};
    std::vector<PointLight> const lights{light};
    glm::ivec2 const centre = projectedPixel(*r, cam, light.position);
    for (LightingMode mode : {LightingMode::Quad, LightingMode::Volumes, LightingMode::Forward}) {
        std::string const name(enumName(kLightingModeNames, mode));
        auto frame = [&](bool cubes, bool wires, DebugView view) {
            PipelineSettings s = plainSettings();
            s.mode = mode;
            s.lightCubes = cubes;
            s.volumeWireframes = wires;
            s.view = view;
            FrameStats const st = r->render({cam, lights, s});
            EXPECT_EQ(st.glErrors, 0u) << name;
            return std::pair{r->readAttachment(Attachment::Lighting), r->readAttachment(Attachment::Final)};
        };
        auto const [lit, display] = frame(false, false, DebugView::Final);
        // Pixels of the display that changed (any channel by more than one RGBA8 step).
        auto changed = [&](FloatImage const& other) {
            int n = 0;
            for (int y = 0; y < other.height; ++y)
                for (int x = 0; x < other.width; ++x)
                    n += glm::length(rgbAt(other, {x, y}) - rgbAt(display, {x, y})) > 1.5f / 255.0f;
            return n;
        };
        auto const [litCubes, displayCubes] = frame(true, false, DebugView::Final);
        EXPECT_EQ(litCubes.pixels, lit.pixels) << name << ": the cubes are not in the lit image";
        // The cube at the light's centre, tonemapped (RGBA8 rounding and GPU exp/pow: 2 steps).
        EXPECT_NEAR(glm::length(rgbAt(displayCubes, centre) - tonemapExposure(light.color * kLightCubeEmissive)), 0.0f,
                    2.0f / 255.0f)
            << name;
        int const cubePixels = changed(displayCubes);
        EXPECT_GT(cubePixels, 0) << name;
        EXPECT_LT(cubePixels, 40) << name << ": a small cube, not the whole image";  // 0.6 % of the scene radius
        auto const [litWires, displayWires] = frame(false, true, DebugView::Final);
        EXPECT_EQ(litWires.pixels, lit.pixels) << name << ": the wireframes are not in the lit image";
        EXPECT_GT(changed(displayWires), 20) << name << ": the sphere's lines are on the display";
        // A view of the G-buffer shows data the overlays would hide: none are drawn over it.
        if (mode != LightingMode::Forward) {
            FloatImage const normals = frame(false, false, DebugView::Normal).second;
            EXPECT_EQ(frame(true, true, DebugView::Normal).second.pixels, normals.pixels) << name;
        }
    }
}
