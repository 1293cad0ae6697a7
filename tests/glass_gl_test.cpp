// Transparency goes forward (issue 47): blended panes are absent from every G-buffer attachment, the
// forward pass lights them with the same lights and equation and blends them over the lit image
// back to front, depth-tested against the depth the depth-copy step put in the lit target.
#include "core/frame_passes.h"
#include "core/shading_cpu.h"
#include "gl_fixture.h"
#include "scene/default_scene.h"
#include "scene/draw_order.h"
#include "scene/mesh_builder.h"
#include "test_scenes.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

using namespace gbl;
using gbl::test::GlTest;

namespace {

constexpr int kW = 64, kH = 48;
constexpr glm::vec4 kPaneColor{0.2f, 0.45f, 0.9f, 0.4f};
constexpr float kPaneSpecular = 0.8f;
constexpr float kPaneZ = 1.5f;

using test::lookingAt;
using test::Ray;
Ray pixelRay(Camera const& c, int x, int y) {
    return test::pixelRay(c, kW, kH, x, y);
}

// A blended, double-sided material of `color`.
Material glassMaterial(glm::vec4 color) {
    Material m;
    m.name = "test glass";
    m.baseColorFactor = color;
    m.specularFactor = kPaneSpecular;
    m.alphaMode = AlphaMode::Blend;
    m.doubleSided = true;
    return m;
}

// Adds a `size` pane of `color` in the plane z = `z`, facing +Z, centred on (x, y).
void addPane(SceneData& s, glm::vec4 color, glm::vec2 size, glm::vec3 center) {
    s.materials.push_back(glassMaterial(color));
    MeshData pane = makePlane(size);
    pane.material = int(s.materials.size()) - 1;
    s.meshes.push_back(pane);
    glm::mat4 const model =
        glm::translate(glm::mat4(1.0f), center) * glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1, 0, 0));
    s.instances.push_back({int(s.meshes.size()) - 1, model});
}

// test::floorAndWallScene (the wall in z = 0, facing +Z) with a 3 x 2 pane in front of it.
SceneData wallWithPane() {
    SceneData s = test::floorAndWallScene();
    addPane(s, kPaneColor, {3.0f, 2.0f}, {0.0f, 2.0f, kPaneZ});
    return s;
}

PipelineSettings plainSettings() {
    PipelineSettings s;
    s.lightCubes = false;
    s.ambient = glm::vec3(0.05f);
    return s;
}

PointLight frontLight() {
    PointLight l;
    l.position = {0.8f, 2.3f, 3.0f};
    l.color = {1.0f, 0.9f, 0.8f};
    l.intensity = 2.0f;
    l.kc = 1.0f;
    l.kl = 0.35f;
    l.kq = 0.44f;
    return l;
}

glm::vec3 rgb(FloatImage const& img, int x, int y) {
    return {img.at(x, y, 0), img.at(x, y, 1), img.at(x, y, 2)};
}

class GlassGlTest : public GlTest {
protected:
    Camera camera_ = lookingAt({0.0f, 2.0f, 6.0f}, {0.0f, 2.0f, 0.0f});
    std::vector<PointLight> lights_{frontLight()};
};

}  // namespace

// A pixel behind the pane: the wall lit by the CPU equation from its G-buffer values, the pane lit by
// the CPU equation at the ray's hit on it with its own normal, blended with the pane's alpha.
TEST_F(GlassGlTest, PixelBehindPaneIsCpuBlendOfLitPaneOverLitWall) {
    auto r = makeRenderer(kW, kH);
    ASSERT_FALSE(r->setScene(wallWithPane()));
    PipelineSettings const settings = plainSettings();
    r->render({camera_, lights_, settings});
    FloatImage const pos = r->readAttachment(Attachment::Position);
    FloatImage const nrm = r->readAttachment(Attachment::Normal);
    FloatImage const alb = r->readAttachment(Attachment::AlbedoSpec);
    FloatImage const lit = r->readAttachment(Attachment::Lighting);
    int checked = 0;
    double maxErr = 0.0;
    for (int y = kH / 2 - 6; y <= kH / 2 + 6; y += 3)
        for (int x = kW / 2 - 9; x <= kW / 2 + 9; x += 3) {
            Ray const ray = pixelRay(camera_, x, y);
            float const t = (kPaneZ - ray.origin.z) / ray.dir.z;
            glm::vec3 const onPane = ray.origin + t * ray.dir;
            ASSERT_LT(std::abs(onPane.x), 1.4f) << "pixel " << x << "," << y << " is meant to look through the pane";
            ASSERT_LT(std::abs(onPane.y - 2.0f), 0.9f);
            // The G-buffer holds the wall, not the pane.
            ASSERT_NEAR(pos.at(x, y, 2), 0.0f, 1e-3f) << "pixel " << x << "," << y;
            ShadingInputs wall;
            shadingOf(settings, wall);
            wall.position = {pos.at(x, y, 0), pos.at(x, y, 1), pos.at(x, y, 2)};
            wall.normal = glm::normalize(rgb(nrm, x, y));
            wall.albedo = rgb(alb, x, y);
            wall.specular = alb.at(x, y, 3);
            wall.viewPosition = camera_.position;
            ShadingInputs pane = wall;
            pane.position = onPane;
            pane.normal = {0.0f, 0.0f, 1.0f};  // its +Z side faces the camera
            pane.albedo = glm::vec3(kPaneColor);
            pane.specular = kPaneSpecular;
            glm::vec3 const behind = shadePointCpu(lights_, wall, settings.ambient);
            glm::vec3 const front = shadePointCpu(lights_, pane, settings.ambient);
            glm::vec3 const expected = kPaneColor.a * front + (1.0f - kPaneColor.a) * behind;
            for (int c = 0; c < 3; ++c) {
                // RGBA16F: the wall's lit value rounded once, the blend result once more (2^-11 each).
                double const err = std::abs(double(lit.at(x, y, c)) - double(expected[c]));
                EXPECT_LE(err, 3e-3 * std::max(1.0, double(expected[c]))) << "pixel " << x << "," << y << " ch " << c;
                maxErr = std::max(maxErr, err);
            }
            // Not merely the wall: the pane changed the pixel by more than the bound.
            EXPECT_GT(glm::length(expected - behind), 0.02f);
            ++checked;
        }
    EXPECT_EQ(checked, 5 * 7);
    EXPECT_LT(maxErr, 3e-3);
}

// The glass is in no G-buffer attachment: every attachment of the frame with the pane is bit for bit
// the frame's without it, in every layout; only the lit image differs, and only where the pane is.
TEST_F(GlassGlTest, GlassIsAbsentFromEveryGBufferAttachment) {
    for (std::size_t layout = 0; layout < kGBufferLayoutNames.size(); ++layout) {
        PipelineSettings s = plainSettings();
        s.layout = GBufferLayout(layout);
        auto withGlass = makeRenderer(kW, kH);
        auto without = makeRenderer(kW, kH);
        ASSERT_FALSE(withGlass->setScene(wallWithPane()));
        ASSERT_FALSE(without->setScene(test::floorAndWallScene()));
        withGlass->render({camera_, lights_, s});
        without->render({camera_, lights_, s});
        std::string const name(kGBufferLayoutNames[layout]);
        for (Attachment a : {Attachment::Position, Attachment::Normal, Attachment::AlbedoSpec, Attachment::Emissive,
                             Attachment::Depth}) {
            FloatImage const g = withGlass->readAttachment(a), n = without->readAttachment(a);
            ASSERT_EQ(g.pixels.size(), n.pixels.size());
            EXPECT_TRUE(g.pixels == n.pixels) << name << ": attachment " << int(a) << " differs with the glass";
        }
        FloatImage const g = withGlass->readAttachment(Attachment::Lighting);
        FloatImage const n = without->readAttachment(Attachment::Lighting);
        EXPECT_NE(rgb(g, kW / 2, kH / 2), rgb(n, kW / 2, kH / 2)) << name << ": the pane is not in the lit image";
        EXPECT_EQ(rgb(g, 1, 1), rgb(n, 1, 1)) << name << ": a corner pixel away from the pane changed";
    }
}

// An opaque box between the camera and the pane. With the depth copy (blit or shader) the lit target
// holds the scene's depth and the box hides the pane; with it off the lit target's depth is the
// cleared 1 and the pane draws over the box, as the light cubes draw through walls.
TEST_F(GlassGlTest, WithoutTheDepthCopyThePaneShowsThroughAnOccluder) {
    SceneData occluded = wallWithPane();
    SceneData bare = test::floorAndWallScene();
    for (SceneData* s : {&occluded, &bare}) {
        MeshData box = makeBox({1.0f, 1.0f, 0.4f});
        box.material = 0;
        s->meshes.push_back(box);
        s->instances.push_back(
            {int(s->meshes.size()) - 1, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 2.0f, 3.0f))});
    }
    for (DepthCopy copy : {DepthCopy::Blit, DepthCopy::Shader, DepthCopy::Off}) {
        PipelineSettings s = plainSettings();
        s.depthCopy = copy;
        auto withGlass = makeRenderer(kW, kH);
        auto without = makeRenderer(kW, kH);
        ASSERT_FALSE(withGlass->setScene(occluded));
        ASSERT_FALSE(without->setScene(bare));
        withGlass->render({camera_, lights_, s});
        without->render({camera_, lights_, s});
        FloatImage const pos = without->readAttachment(Attachment::Position);
        ASSERT_NEAR(pos.at(kW / 2, kH / 2, 2), 3.2f, 1e-3f) << "the centre pixel sees the box's front face";
        glm::vec3 const g = rgb(withGlass->readAttachment(Attachment::Lighting), kW / 2, kH / 2);
        glm::vec3 const n = rgb(without->readAttachment(Attachment::Lighting), kW / 2, kH / 2);
        std::string const name(kDepthCopyNames[std::size_t(copy)]);
        if (copy == DepthCopy::Off)
            EXPECT_GT(glm::length(g - n), 0.02f) << name << ": the pane should show through the box";
        else
            EXPECT_EQ(g, n) << name << ": the box should hide the pane";
    }
}

// Two overlapping panes listed front first: the forward pass draws the far one first, so the pixel
// is the near pane over (the far pane over the wall), which differs from the other order.
TEST_F(GlassGlTest, OverlappingPanesBlendBackToFront) {
    glm::vec4 const farColor{0.9f, 0.2f, 0.1f, 0.5f};
    SceneData s = test::floorAndWallScene();
    addPane(s, kPaneColor, {3.0f, 2.0f}, {0.0f, 2.0f, kPaneZ + 1.0f});  // near, listed first
    addPane(s, farColor, {3.0f, 2.0f}, {0.0f, 2.0f, kPaneZ});           // far
    PipelineSettings const settings = plainSettings();
    // Unlit, so the blend order alone decides: no lights, ambient 1, the panes' colours as they are.
    PipelineSettings flat = settings;
    flat.ambient = glm::vec3(1.0f);
    auto r = makeRenderer(kW, kH);
    ASSERT_FALSE(r->setScene(s));
    r->render({camera_, {}, flat});
    FloatImage const lit = r->readAttachment(Attachment::Lighting);
    FloatImage const alb = r->readAttachment(Attachment::AlbedoSpec);
    glm::vec3 const wall = rgb(alb, kW / 2, kH / 2);  // ambient 1 x albedo
    glm::vec3 const nearRgb(kPaneColor), farRgb(farColor);
    glm::vec3 const farThenNear =
        kPaneColor.a * nearRgb + (1.0f - kPaneColor.a) * (farColor.a * farRgb + (1.0f - farColor.a) * wall);
    glm::vec3 const nearThenFar =
        farColor.a * farRgb + (1.0f - farColor.a) * (kPaneColor.a * nearRgb + (1.0f - kPaneColor.a) * wall);
    glm::vec3 const got = rgb(lit, kW / 2, kH / 2);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], farThenNear[c], 3e-3f) << "channel " << c;
    EXPECT_GT(glm::length(farThenNear - nearThenFar), 0.1f) << "the two orders must differ for the test to mean it";
}

// The order itself (scene/draw_order.h): farthest first by view depth, ties in list order.
TEST(DrawOrder, BackToFrontByViewDepth) {
    Camera const cam = lookingAt({0.0f, 0.0f, 10.0f}, {0.0f, 0.0f, 0.0f});
    glm::mat4 const viewProj = cam.projection(1.0f) * cam.view();
    std::vector<glm::vec3> const centers{{0, 0, 5}, {3, 0, -4}, {0, 0, 0}, {-3, 0, -4}, {0, 1, 8}};
    std::vector<std::size_t> const expected{1, 3, 2, 0, 4};
    EXPECT_EQ(backToFrontOrder(centers, viewProj), expected);
}

// The default scene's glass (DefaultSceneOptions::glass): the panes of kGlassPanes added after the
// courtyard, blended and double-sided, leaving the rest of the scene as it was.
TEST(DefaultSceneGlass, OffByDefaultAndAddsThePanesWhenOn) {
    SceneData const plain = makeDefaultScene({0});
    SceneData const glass = makeDefaultScene({0, true});
    ASSERT_EQ(glass.meshes.size(), plain.meshes.size() + std::size(kGlassPanes));
    ASSERT_EQ(glass.instances.size(), plain.instances.size() + std::size(kGlassPanes));
    for (Material const& m : plain.materials) EXPECT_NE(m.alphaMode, AlphaMode::Blend) << m.name;
    for (std::size_t i = 0; i < std::size(kGlassPanes); ++i) {
        MeshInstance const& inst = glass.instances[plain.instances.size() + i];
        Material const& m = glass.materials[std::size_t(glass.meshes[std::size_t(inst.mesh)].material)];
        EXPECT_EQ(m.name, kGlassPanes[i].name);
        EXPECT_EQ(m.alphaMode, AlphaMode::Blend);
        EXPECT_TRUE(m.doubleSided);
        EXPECT_EQ(m.baseColorFactor, kGlassPanes[i].color);
        glm::vec3 const c(inst.model * glm::vec4(0, 0, 0, 1));
        EXPECT_NEAR(glm::distance(c, kGlassPanes[i].center), 0.0f, 1e-5f);
    }
}

// The glass outline overlay (pipeline field glass_outline): on the albedo view, which the glass is
// absent from, magenta hatching where the pane is and nowhere else; off, no pixel is magenta.
TEST_F(GlassGlTest, TheOutlineHatchesThePaneOnTheAlbedoView) {
    auto r = makeRenderer(kW, kH);
    ASSERT_FALSE(r->setScene(wallWithPane()));
    auto magentaInside = [&](PipelineSettings const& s, int& outside) {
        r->render({camera_, lights_, s});
        FloatImage const img = r->readAttachment(Attachment::Final);
        int inside = 0;
        outside = 0;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                bool const magenta = img.at(x, y, 0) == 1.0f && img.at(x, y, 1) == 0.0f && img.at(x, y, 2) == 1.0f;
                if (!magenta) continue;
                Ray const ray = pixelRay(camera_, x, y);
                glm::vec3 const p = ray.origin + (kPaneZ - ray.origin.z) / ray.dir.z * ray.dir;
                bool const onPane = std::abs(p.x) < 1.5f + 0.1f && std::abs(p.y - 2.0f) < 1.0f + 0.1f;
                (onPane ? inside : outside)++;
            }
        return inside;
    };
    PipelineSettings s = plainSettings();
    s.view = DebugView::Albedo;
    int outside = 0;
    EXPECT_EQ(magentaInside(s, outside), 0) << "no outline unless asked for";
    s.glassOutline = true;
    int const inside = magentaInside(s, outside);
    // The pane covers roughly 3 x 2 units at 4.5 units: hundreds of pixels, a third of them hatched.
    EXPECT_GT(inside, 100);
    EXPECT_EQ(outside, 0);
    auto const passes = r->framePasses({camera_, lights_, s});
    ASSERT_GE(passes.size(), 2u);
    EXPECT_EQ(passes.back().id, PassId::GlassOutline) << "after the display pass, on the albedo view too";
}

// Light cubes and glass (the cubes are drawn on the display image after the lit image's panes): a
// cube behind the pane is seen through it, the pane blended over the cube; a cube in front of the
// pane is drawn over it. At every pixel a cube covers, against the same frame without the pane.
TEST_F(GlassGlTest, ACubeBehindThePaneIsSeenThroughItAndOneInFrontCoversIt) {
    constexpr int w = 160, h = 90;
    PointLight behind = frontLight(), front = frontLight();
    behind.position = {-0.7f, 2.0f, 0.7f};  // between the wall (z = 0) and the pane (z = 1.5)
    behind.color = {1.0f, 0.25f, 0.2f};
    front.position = {0.7f, 2.0f, 2.5f};  // between the pane and the camera
    std::vector<PointLight> const lights{behind, front};
    PipelineSettings s = plainSettings();
    s.lightCubes = true;
    auto withPane = makeRenderer(w, h);
    auto bare = makeRenderer(w, h);
    ASSERT_FALSE(withPane->setScene(wallWithPane()));
    ASSERT_FALSE(bare->setScene(test::floorAndWallScene()));
    FrameStats const st = withPane->render({camera_, lights, s});
    EXPECT_EQ(st.glErrors, 0u);
    FloatImage const shown = withPane->readAttachment(Attachment::Final);
    FloatImage const lit = withPane->readAttachment(Attachment::Lighting);
    bare->render({camera_, lights, s});
    FloatImage const cubes = bare->readAttachment(Attachment::Final);
    FloatImage const wallLit = bare->readAttachment(Attachment::Lighting);
    PipelineSettings noCubes = s;
    noCubes.lightCubes = false;
    bare->render({camera_, lights, noCubes});
    FloatImage const noCubesShown = bare->readAttachment(Attachment::Final);
    // The display's tonemap (shaders/tonemap.glsl, exposure curve, the default).
    ASSERT_EQ(s.tonemap, Tonemap::Exposure);
    auto const tonemap = [&](float v) { return std::pow(1.0f - std::exp(-v * s.exposure), 1.0f / 2.2f); };
    float const a = kPaneColor.a;
    int behindPixels = 0, frontPixels = 0;
    double worst = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            glm::vec3 const cube = rgb(cubes, x, y);
            if (glm::length(cube - rgb(noCubesShown, x, y)) < 0.05f) continue;  // no cube here
            glm::vec3 const got = rgb(shown, x, y);
            if (x < w / 2) {  // the cube behind the pane: the pane over it
                ++behindPixels;
                EXPECT_GT(glm::length(got - cube), 0.05f) << "pixel " << x << "," << y << " shows the bare cube";
                for (int c = 0; c < 3; ++c) {
                    // The pane's own lit value, from the lit image: lit = a pane + (1 - a) wall.
                    float const pane = (lit.at(x, y, c) - (1.0f - a) * wallLit.at(x, y, c)) / a;
                    float const expected = a * tonemap(pane) + (1.0f - a) * cube[c];
                    // RGBA8 display: the cube and the result each rounded (1/255), the lit values fp16.
                    double const err = std::abs(double(got[c]) - double(expected));
                    worst = std::max(worst, err);
                    EXPECT_LE(err, 3.0 / 255.0) << "pixel " << x << "," << y << " channel " << c;
                }
            } else {  // the cube in front: drawn over the pane, exactly its colour
                ++frontPixels;
                EXPECT_EQ(got, cube) << "pixel " << x << "," << y;
            }
        }
    EXPECT_GT(behindPixels, 10) << "the cube behind the pane should cover some pixels";
    EXPECT_GT(frontPixels, 10) << "the cube in front of the pane should cover some pixels";
    RecordProperty("worst_error_behind", std::to_string(worst));
}
