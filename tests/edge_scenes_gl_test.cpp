// The edge-case scenes every lighting mode must survive (issue 25): each mode x G-buffer layout x
// accumulation (and prepass's light volumes, msaa 4 in quad and volumes) over scenes that once crashed or that sit at a
// limit, on small frames. A frame fails on any GL error, any shader-check report (GBL_SHADER_CHECKS=1: an out-of-range
// access in a compute shader, named) or a non-finite lit value; a crash fails the process. ctest runs this binary
// several times, each in a fresh process (tests/CMakeLists.txt), since a read of undefined memory can pass once: tiled
// mode once crashed in about half the runs of a two-triangle scene.
#include "gl_fixture.h"
#include "test_scenes.h"

#include "core/light_math.h"

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace gbl::test {
namespace {

struct EdgeScene {
    std::string name;
    std::function<std::vector<PointLight>()> lights;
    Camera camera;
};

// Looks at the floor's centre from above and to the side, with the horizon (background tiles,
// which hold no geometry) in the top of the frame.
Camera horizonCamera() {
    Camera c;
    c.position = {0.0f, 3.0f, 14.0f};
    c.lookAt({0.0f, 1.0f, 0.0f});
    return c;
}

PointLight point(glm::vec3 p, float intensity = 1.0f) {
    PointLight l;
    l.position = p;
    l.intensity = intensity;
    l.kc = 1.0f;
    l.kl = 0.35f;
    l.kq = 0.44f;
    return l;
}

PointLight directional(glm::vec3 d) {
    PointLight l;
    l.kind = LightKind::Directional;
    l.direction = d;
    l.color = {1.0f, 0.9f, 0.8f};
    l.intensity = 2.0f;
    return l;
}

PointLight spotDown() {
    PointLight l = point({0.0f, 4.0f, 0.0f}, 40.0f);
    l.kind = LightKind::Spot;
    l.direction = {0.0f, -1.0f, 0.0f};
    l.innerConeDeg = glm::degrees(0.3f);
    l.outerConeDeg = glm::degrees(0.5f);
    return l;
}

std::vector<EdgeScene> edgeScenes() {
    Camera const c = horizonCamera();
    Camera inside = c;
    inside.position = {0.0f, 1.0f, 2.0f};
    inside.lookAt({0.0f, 0.0f, -4.0f});
    std::vector<EdgeScene> s;
    // Nothing drawn at all (the camera looks up at the sky), and the wall alone in the frame's top
    // corner: tiles without geometry, also the first tiles a work-group thread runs.
    Camera sky = c;
    sky.lookAt(c.position + glm::vec3(0.0f, 1.0f, -0.2f));
    Camera corner = c;
    corner.position = {-6.0f, 1.0f, 10.0f};
    corner.lookAt({-9.0f, -1.0f, 0.0f});
    s.push_back({"sky_only",
                 [] {
                     return std::vector<PointLight>{spotDown(), point({0.0f, 6.0f, 10.0f}, 3.0f)};
                 },
                 sky});
    s.push_back({"geometry_in_a_corner",
                 [] {
                     return std::vector<PointLight>{directional({0.0f, -0.7f, -0.7f}), spotDown()};
                 },
                 corner});
    s.push_back({"no_lights", [] { return std::vector<PointLight>{}; }, c});
    s.push_back({"directional_only", [] { return std::vector<PointLight>{directional({0.0f, -0.7f, -0.7f})}; }, c});
    s.push_back({"spot_straight_down", [] { return std::vector<PointLight>{spotDown()}; }, c});
    s.push_back({"point_on_surface", [] { return std::vector<PointLight>{point({0.0f, 0.0f, 0.0f}, 4.0f)}; }, c});
    s.push_back({"radius_zero",
                 [] {
                     PointLight l = point({0.0f, 1.0f, 0.0f}, 0.0f);  // no intensity: radius 0
                     return std::vector<PointLight>{l, point({2.0f, 1.0f, 0.0f}, 0.0f)};
                 },
                 c});
    s.push_back({"all_outside_frustum",
                 [] {
                     std::vector<PointLight> out;
                     for (int i = 0; i < 8; ++i) out.push_back(point({float(i) - 4.0f, 1.0f, 30.0f}, 1.0f));
                     return out;
                 },
                 c});
    s.push_back({"camera_inside_volume",
                 [] {
                     return std::vector<PointLight>{point({0.0f, 1.0f, 2.0f}, 30.0f), spotDown()};
                 },
                 inside});
    // More lights than one tile's bin holds (kTileBinMaxLights), all over the same few pixels.
    s.push_back({"crowded_tile",
                 [] {
                     std::vector<PointLight> out;
                     for (int i = 0; i < 1100; ++i)
                         out.push_back(point({0.01f * float(i % 10), 0.3f, 0.01f * float(i / 10)}, 0.5f));
                     return out;
                 },
                 c});
    s.push_back({"every_kind",
                 [] {
                     return std::vector<PointLight>{directional({0.3f, -1.0f, 0.2f}), spotDown(),
                                                    point({3.0f, 0.5f, 1.0f}, 3.0f)};
                 },
                 c});
    return s;
}

// Every mode, and the paths inside a mode that run other passes: prepass's light volumes and msaa's
// edges strategy (detection, simple and complex lighting, resolve) in quad and volumes.
struct Variant {
    LightingMode mode;
    PrepassLights prepassLights = PrepassLights::Quad;
    Msaa msaa = Msaa::Off;
};
constexpr Variant kVariants[] = {{LightingMode::Quad},
                                 {LightingMode::Volumes},
                                 {LightingMode::Tiled},
                                 {LightingMode::Forward},
                                 {LightingMode::Clustered},
                                 {LightingMode::ForwardPlus},
                                 {LightingMode::Prepass},
                                 {LightingMode::Prepass, PrepassLights::Volumes},
                                 {LightingMode::Quad, PrepassLights::Quad, Msaa::X4},
                                 {LightingMode::Volumes, PrepassLights::Quad, Msaa::X4}};
constexpr GBufferLayout kLayouts[] = {GBufferLayout::Classic, GBufferLayout::Packed, GBufferLayout::Naive8,
                                      GBufferLayout::Rgb10a2};
constexpr LightAccumulation kAccumulations[] = {LightAccumulation::Single, LightAccumulation::Split};

class EdgeScenesGlTest : public GlTest {
protected:
    // Renders each scene in every mode, layout and accumulation at width x height; each frame's
    // failure names the combination. One renderer for all: the layout is the outer loop, so each
    // layout's programs build once.
    void renderEverywhere(std::vector<EdgeScene> const& scenes, int width, int height) {
        auto renderer = makeRenderer(width, height);
        ASSERT_FALSE(renderer->setScene(floorAndWallScene()).has_value());
        for (GBufferLayout layout : kLayouts)
            for (EdgeScene const& scene : scenes) renderScene(*renderer, scene, layout, width, height);
    }

    void renderScene(Renderer& renderer, EdgeScene const& scene, GBufferLayout layout, int width, int height) {
        std::vector<PointLight> const lights = scene.lights();
        for (Variant const& v : kVariants) {
            LightingMode const mode = v.mode;
            if (auto why = renderer.modeUnavailable(mode)) {
                if (mode == LightingMode::Tiled || mode == LightingMode::Clustered || mode == LightingMode::ForwardPlus)
                    continue;  // no compute
                FAIL() << *why;
            }
            for (LightAccumulation acc : kAccumulations) {
                FrameInput in;
                in.camera = scene.camera;
                in.lights = lights;
                in.settings.mode = mode;
                in.settings.layout = layout;
                in.settings.accumulation = acc;
                in.settings.cull = CullMode::Stencil;
                in.settings.volumeWireframes = true;
                in.settings.prepassLights = v.prepassLights;
                in.settings.msaa = v.msaa;
                std::uint64_t const errors = glErrorsSinceSetUp();
                FrameStats const stats = renderer.render(in);
                std::string const what = scene.name + " " + std::to_string(width) + "x" + std::to_string(height) +
                                         " mode " + std::to_string(int(mode)) + " layout " +
                                         std::to_string(int(layout)) + " accumulation " + std::to_string(int(acc)) +
                                         " prepass lights " + std::to_string(int(v.prepassLights)) + " msaa " +
                                         std::to_string(int(v.msaa));
                ASSERT_EQ(glErrorsSinceSetUp(), errors) << what << ": GL errors";
                ASSERT_TRUE(stats.shaderCheckReport.empty()) << what << ": " << stats.shaderCheckReport;
                EXPECT_EQ(stats.modeUsed, mode) << what << ": " << stats.fallbackReason;
                FloatImage const lit = renderer.readAttachment(Attachment::Lighting);
                ASSERT_EQ(lit.width, width);
                std::size_t bad = 0;
                for (float v : lit.pixels) bad += std::isfinite(v) ? 0 : 1;
                ASSERT_EQ(bad, 0u) << what << ": non-finite lit values";
            }
        }
    }
};

TEST_F(EdgeScenesGlTest, EveryModeLayoutAndAccumulationSurvivesEachScene) {
    renderEverywhere(edgeScenes(), 96, 64);
}

// One pixel, and one row of tiles 257 wide: the grids' edges (partial tiles, a single tile).
TEST_F(EdgeScenesGlTest, DegenerateFrameSizes) {
    std::vector<EdgeScene> scenes;
    for (EdgeScene const& scene : edgeScenes())
        if (scene.name == "every_kind" || scene.name == "directional_only" || scene.name == "crowded_tile")
            scenes.push_back(scene);
    renderEverywhere(scenes, 1, 1);
    if (HasFatalFailure()) return;
    renderEverywhere(scenes, 4097, 3);
}

}  // namespace
}  // namespace gbl::test
