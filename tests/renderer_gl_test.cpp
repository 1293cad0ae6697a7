// The deferred core on a headless context: G-buffer contents against analytic values, the
// lighting pass against the CPU equation, the blit step, resizing and shader hot reload.
#include "core/frame_passes.h"
#include "core/shading_cpu.h"
#include "gl/shader_bindings.h"
#include "gl/shader_library.h"
#include "gl_fixture.h"
#include "gpu/light_buffer.h"
#include "test_scenes.h"

#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>

using namespace gbl;
using gbl::test::GlTest;

namespace {

using test::lookingAt;
using test::pixelRay;
using test::Ray;

PipelineSettings plainSettings() {
    PipelineSettings s;
    s.lightCubes = false;
    s.ambient = glm::vec3(0.03f);
    return s;
}

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
    PointLight light;
    light.position = {2.5f, 1.0f, 0.0f};
    light.color = {1.0f, 0.8f, 0.6f};
    light.intensity = 1.5f;
    light.kc = 1.0f;
    light.kl = 0.7f;
    light.kq = 1.8f;  // radius ~6.2: part of the visible floor is lit, part lies beyond
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

TEST_F(RendererGlTest, ResizeToZeroAndBackKeepsWorking) {
    auto r = makeRenderer(40, 30);
    ASSERT_FALSE(r->setScene(test::floorScene()));
    Camera const cam = lookingAt({0.0f, 5.0f, 5.0f}, {0.0f, 0.0f, 0.0f});
    r->render({cam, {}, plainSettings()});
    r->resizeTargets(0, 0);
    EXPECT_EQ(r->texture(Attachment::Final), 0u);
    FrameStats const empty = r->render({cam, {}, plainSettings()});
    EXPECT_EQ(empty.width, 0);
    EXPECT_TRUE(empty.passes.empty()) << "nothing is drawn into 0x0 targets";
    EXPECT_EQ(r->readAttachment(Attachment::Final).width, 0);
    r->resizeTargets(33, 17);  // odd sizes: no assumption of even or tile-aligned sizes
    FrameStats const back = r->render({cam, {}, plainSettings()});
    EXPECT_EQ(back.width, 33);
    EXPECT_FALSE(back.passes.empty());
    FloatImage const n = r->readAttachment(Attachment::Normal);
    EXPECT_EQ(n.width, 33);
    EXPECT_EQ(n.height, 17);
    EXPECT_EQ(n.at(16, 16, 1), 1.0f) << "the floor is drawn again after the resize";
    // Every target is checked for completeness when created; an incomplete one throws.
    EXPECT_NO_THROW(r->resizeTargets(1, 1));
}

TEST_F(RendererGlTest, FailedHotReloadKeepsLastGoodProgram) {
    namespace fs = std::filesystem;
    fs::path const dir = fs::temp_directory_path() / ("gbl_reload_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::copy_file(fs::path(GBL_SOURCE_DIR) / "shaders" / "depth_copy.frag", dir / "depth_copy.frag",
                  fs::copy_options::overwrite_existing);
    ShaderLibrary lib(dir);
    std::string log;
    ASSERT_TRUE(lib.add(ProgramId::DepthCopy, &log)) << log;
    GLuint const good = lib.get(ProgramId::DepthCopy).id();
    EXPECT_TRUE(lib.reloadChanged().empty()) << "nothing changed yet";

    auto writeLater = [&](std::string const& text) {
        // File times can be coarse; make sure the new write is seen as a change.
        auto const before = fs::last_write_time(dir / "depth_copy.frag");
        std::ofstream(dir / "depth_copy.frag") << text;
        fs::last_write_time(dir / "depth_copy.frag", before + std::chrono::seconds(1));
    };
    writeLater("#version 330 core\nvoid main() { this is not glsl; }\n");
    auto messages = lib.reloadChanged();
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_NE(messages[0].find("keeping the last good one"), std::string::npos) << messages[0];
    EXPECT_NE(messages[0].find("depth_copy.frag"), std::string::npos) << "the log names the file: " << messages[0];
    EXPECT_EQ(lib.get(ProgramId::DepthCopy).id(), good) << "the last good program stays in use";

    std::ifstream original(fs::path(GBL_SOURCE_DIR) / "shaders" / "depth_copy.frag");
    writeLater(std::string(std::istreambuf_iterator<char>(original), {}));
    messages = lib.reloadChanged();
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_NE(messages[0].find("reloaded"), std::string::npos) << messages[0];
    EXPECT_NE(lib.get(ProgramId::DepthCopy).id(), good);
    fs::remove_all(dir);
}

TEST_F(RendererGlTest, GpuTimingsCoverEveryPass) {
    auto r = makeRenderer(32, 32);
    ASSERT_FALSE(r->setScene(test::floorScene()));
    FrameStats const s = r->render({lookingAt({0, 5, 5}, {0, 0, 0}), {}, plainSettings()});
    std::vector<std::string> names;
    for (auto const& p : s.passes) {
        names.push_back(p.name);
        EXPECT_GE(p.gpuMs, 0.0);
    }
    EXPECT_EQ(names, (std::vector<std::string>{"geometry", "lighting", "depth_copy", "forward", "display"}));
}

TEST_F(RendererGlTest, TheTimedPassesAreTheDeclaredOnes) {
    // core/frame_passes.h describes the frame render() runs: the timer's names, in order, are the
    // declared passes' for every mode and layout, with and without the optional passes.
    auto r = makeRenderer(32, 24);
    ASSERT_FALSE(r->setScene(test::floorScene()));
    PointLight light;
    light.position = {0, 1, 0};
    std::vector<PointLight> const lights{light};
    int frames = 0;
    for (std::size_t layout = 0; layout < kGBufferLayoutNames.size(); ++layout)
        for (std::size_t mode = 0; mode < kLightingModeNames.size(); ++mode)
            for (CullMode cull : {CullMode::Front, CullMode::Stencil})
                for (bool extras : {false, true}) {
                    PipelineSettings s = plainSettings();
                    s.layout = GBufferLayout(layout);
                    s.mode = LightingMode(mode);
                    s.cull = cull;
                    s.lightCubes = s.volumeWireframes = extras;
                    s.accumulation = extras ? LightAccumulation::Split : LightAccumulation::Single;
                    s.view = extras ? DebugView::Heatmap : DebugView::Final;
                    FrameStats const st = r->render({lookingAt({0, 5, 5}, {0, 0, 0}), lights, s});
                    s.mode = st.modeUsed;  // as it ran (a mode this context lacks falls back to quad)
                    std::vector<std::string> timed, declared;
                    for (auto const& p : st.passes) timed.push_back(p.name);
                    for (PassDecl const& p : framePasses(s)) declared.emplace_back(p.name());
                    EXPECT_EQ(timed, declared) << kGBufferLayoutNames[layout] << " " << kLightingModeNames[mode];
                    EXPECT_EQ(st.glErrors, 0u);
                    ++frames;
                }
    EXPECT_EQ(frames, 4 * 7 * 2 * 2);  // layouts, modes (forward+ the sixth, prepass the seventh), cull modes, extras
}

namespace {
float maxAbs(FloatImage const& image, int channels) {
    float m = 0.0f;
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        if (int(i % std::size_t(image.channels)) < channels) m = std::max(m, std::abs(image.pixels[i]));
    return m;
}
}  // namespace

TEST_F(RendererGlTest, StoppingAfterGeometryLeavesTheLitTargetCleared) {
    int const w = 48, h = 32;
    auto r = makeRenderer(w, h);
    ASSERT_FALSE(r->setScene(test::floorScene()));
    PointLight light;
    light.position = {0.0f, 1.0f, 0.0f};
    std::vector<PointLight> const lights{light};
    Camera const cam = lookingAt({0, 5, 5}, {0, 0, 0});
    for (LightingMode mode :
         {LightingMode::Quad, LightingMode::Volumes, LightingMode::Tiled, LightingMode::Clustered}) {
        PipelineSettings s = plainSettings();
        s.mode = mode;
        s.lightCubes = true;
        std::string const name(enumName(kLightingModeNames, mode));
        r->render({cam, lights, s});  // a whole frame first: its light must not survive the stopped one
        ASSERT_GT(maxAbs(r->readAttachment(Attachment::Lighting), 3), 0.0f) << name;
        FrameInput input{cam, lights, s};
        input.stopAfter = PassId::Geometry;
        FrameStats const st = r->render(input);
        EXPECT_EQ(st.stoppedAfter, PassId::Geometry) << name;
        EXPECT_EQ(st.fallbackReason, "") << name;
        std::vector<std::string> ran;
        for (auto const& p : st.passes) ran.push_back(p.name);
        EXPECT_EQ(ran, (std::vector<std::string>{"geometry", "display"})) << name;
        // Exactly zero: the stopped frame cleared the lit target and nothing drew into it since.
        EXPECT_EQ(maxAbs(r->readAttachment(Attachment::Lighting), 4), 0.0f) << name;
        EXPECT_EQ(maxAbs(r->readAttachment(Attachment::Final), 3), 0.0f) << name << ": the display shows it black";
        // The G-buffer is filled: the floor covers the lower part of the view with its albedo.
        FloatImage const pos = r->readAttachment(Attachment::Position);
        FloatImage const alb = r->readAttachment(Attachment::AlbedoSpec);
        EXPECT_EQ(pos.at(w / 2, h - 1, 3), 1.0f) << name;
        EXPECT_NEAR(alb.at(w / 2, h - 1, 0), test::kPlaneAlbedo.x, 1.0f / 255.0f) << name;  // RGBA8: one step
        EXPECT_EQ(st.glErrors, 0u) << name;
    }
}

TEST_F(RendererGlTest, StoppingAfterLightingGivesTheLightSumWithoutCubes) {
    int const w = 48, h = 32;
    auto r = makeRenderer(w, h);
    ASSERT_FALSE(r->setScene(test::floorScene()));  // no blended surfaces: the forward pass adds nothing
    PointLight light;
    light.position = {0.0f, 1.0f, 0.0f};
    std::vector<PointLight> const lights{light};
    Camera const cam = lookingAt({0, 5, 5}, {0, 0, 0});
    // The largest difference of the colour channels (alpha is not part of the light sum).
    auto maxDiff = [](FloatImage const& a, FloatImage const& b) {
        float m = 0.0f;
        for (std::size_t i = 0; i < a.pixels.size(); ++i)
            if (i % 4 != 3) m = std::max(m, std::abs(a.pixels[i] - b.pixels[i]));
        return m;
    };
    for (LightingMode mode :
         {LightingMode::Quad, LightingMode::Volumes, LightingMode::Tiled, LightingMode::Clustered}) {
        std::string const name(enumName(kLightingModeNames, mode));
        PipelineSettings s = plainSettings();
        s.mode = mode;
        s.lightCubes = false;
        r->render({cam, lights, s});
        FloatImage const withoutCubes = r->readAttachment(Attachment::Lighting);
        FloatImage const displayWithoutCubes = r->readAttachment(Attachment::Final);
        s.lightCubes = true;
        r->render({cam, lights, s});
        FloatImage const withCubes = r->readAttachment(Attachment::Lighting);
        FloatImage const displayWithCubes = r->readAttachment(Attachment::Final);
        FrameInput input{cam, lights, s};
        input.stopAfter = PassId::Lighting;
        FrameStats const st = r->render(input);
        EXPECT_EQ(st.stoppedAfter, PassId::Lighting) << name;
        FloatImage const stopped = r->readAttachment(Attachment::Lighting);
        ASSERT_EQ(stopped.pixels.size(), withoutCubes.pixels.size());
        EXPECT_GT(maxAbs(stopped, 3), 0.0f) << name << ": the light sum is there";
        // The same passes drew the same light into the same target: equal to the bit. The cubes are an
        // overlay on the display image, so the whole frame's lit image is the same with them.
        EXPECT_EQ(maxDiff(stopped, withoutCubes), 0.0f) << name << ": stopped after lighting = a frame without cubes";
        EXPECT_EQ(maxDiff(stopped, withCubes), 0.0f) << name << ": the lit image holds no cube";
        // On the display, the stopped frame shows no cube: the cube (kLightCubeEmissive x white,
        // tonemapped to 0.88) is far brighter than the floor there.
        FloatImage const stoppedDisplay = r->readAttachment(Attachment::Final);
        EXPECT_EQ(maxDiff(stoppedDisplay, displayWithoutCubes), 0.0f) << name;
        EXPECT_GT(maxDiff(stoppedDisplay, displayWithCubes), 0.3f) << name << ": the full frame shows the cube";
        EXPECT_EQ(st.glErrors, 0u) << name;
    }
}

TEST_F(RendererGlTest, AStopThisFrameDoesNotRunIsReportedAndTheWholeFrameRuns) {
    auto r = makeRenderer(32, 24);
    ASSERT_FALSE(r->setScene(test::floorScene()));
    FrameInput input{lookingAt({0, 5, 5}, {0, 0, 0}), {}, plainSettings()};
    input.stopAfter = PassId::LightLists;  // quad mode builds no light lists
    EXPECT_EQ(r->framePasses(input).size(), 5u);
    FrameStats const st = r->render(input);
    EXPECT_EQ(st.stoppedAfter, std::nullopt);
    EXPECT_NE(st.fallbackReason.find("cannot stop after 'light_lists'"), std::string::npos) << st.fallbackReason;
    EXPECT_EQ(st.passes.size(), 5u);
    EXPECT_EQ(st.glErrors, 0u);
}

TEST_F(RendererGlTest, EverySamplerReadsTheUnitOfBindingsGlsl) {
    // After linking, the library points each sampler at its slot of shaders/bindings.glsl; a
    // sampler missing from the table would silently read unit 0.
    ShaderLibrary lib("");
    std::map<std::string, int> slots;
    for (auto const& s : slot::kSamplerSlots) slots[s.uniform] = s.unit;
    int samplers = 0;
    for (ProgramInfo const& info : programTable()) {
        if ((info.group == ProgramGroup::Tiled || info.group == ProgramGroup::ForwardPlus) && !caps().computeShaders)
            continue;
        std::string log;
        ASSERT_TRUE(lib.add(info.id, &log)) << info.desc.name << ": " << log;
        GLuint const program = lib.get(info.id).id();
        GLint count = 0;
        glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
        std::map<int, std::string> unitUsers;
        for (GLint i = 0; i < count; ++i) {
            char name[128];
            GLint size = 0;
            GLenum type = 0;
            glGetActiveUniform(program, GLuint(i), sizeof name, nullptr, &size, &type, name);
            bool const sampler = type == GL_SAMPLER_2D || type == GL_SAMPLER_BUFFER || type == GL_INT_SAMPLER_BUFFER;
            if (!sampler) continue;
            ++samplers;
            auto const it = slots.find(name);
            ASSERT_NE(it, slots.end()) << info.desc.name << ": sampler " << name << " has no slot in bindings.glsl";
            GLint unit = -1;
            glGetUniformiv(program, glGetUniformLocation(program, name), &unit);
            EXPECT_EQ(unit, it->second) << info.desc.name << ": " << name;
            // Two samplers on one unit within a program would read the same texture.
            EXPECT_TRUE(unitUsers.emplace(unit, name).second)
                << info.desc.name << ": " << name << " and " << unitUsers[unit] << " share unit " << unit;
        }
    }
    EXPECT_GT(samplers, 20) << "the programs declare samplers; none found means the query is wrong";
}

TEST_F(RendererGlTest, VolumeProgramThatFailsToBuildFallsBackToQuadWithTheReason) {
    namespace fs = std::filesystem;
    // A shader directory whose light_volume.frag is broken, seen by hot reload before the
    // volumes mode is first used: building its programs then fails inside render().
    fs::path const dir = fs::temp_directory_path() / ("gbl_broken_volume_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::copy_file(fs::path(GBL_SOURCE_DIR) / "shaders" / "light_volume.frag", dir / "light_volume.frag",
                  fs::copy_options::overwrite_existing);
    setenv("GBL_SHADER_DIR", dir.c_str(), 1);
    auto r = makeRenderer(48, 32);
    unsetenv("GBL_SHADER_DIR");
    auto const before = fs::last_write_time(dir / "light_volume.frag");
    std::ofstream(dir / "light_volume.frag") << "#version 330 core\nvoid main() { this is not glsl; }\n";
    fs::last_write_time(dir / "light_volume.frag", before + std::chrono::seconds(1));
    r->reloadChangedShaders();

    ASSERT_FALSE(r->setScene(test::floorScene()));
    Camera const cam = lookingAt({0.0f, 5.0f, 5.0f}, {0.0f, 0.0f, 0.0f});
    PointLight light;
    light.position = {0.0f, 1.0f, 0.0f};
    std::vector<PointLight> const lights{light};
    PipelineSettings volumes = plainSettings();
    volumes.mode = LightingMode::Volumes;
    FrameStats const st = r->render({cam, lights, volumes});
    EXPECT_EQ(st.modeUsed, LightingMode::Quad);
    EXPECT_NE(st.fallbackReason.find("light_volume"), std::string::npos) << st.fallbackReason;
    EXPECT_NE(st.fallbackReason.find("quad"), std::string::npos) << st.fallbackReason;
    auto const why = r->modeUnavailable(LightingMode::Volumes);
    ASSERT_TRUE(why.has_value());
    EXPECT_NE(why->find("volumes mode is unavailable"), std::string::npos) << *why;
    EXPECT_FALSE(r->modeUnavailable(LightingMode::Quad));
    // What ran is exactly the quad pass.
    FloatImage const fallback = r->readAttachment(Attachment::Lighting);
    r->render({cam, lights, plainSettings()});
    EXPECT_EQ(fallback.pixels, r->readAttachment(Attachment::Lighting).pixels);
    fs::remove_all(dir);
}
