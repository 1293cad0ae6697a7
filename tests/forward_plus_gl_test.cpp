// forward+ (a depth pre-pass, the tiled light lists, forward shading over its tile's list) against
// forward, which shades every light at every fragment: the same image, the camera inside a light's
// volume included; its declared passes run, its lists are counted on the shared heat scale.
#include "core/light_math.h"
#include "lighting_compare.h"
#include "scene/default_scene.h"
#include "scene/mesh_builder.h"
#include "test_scenes.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>

using namespace gbl;
using namespace gbl::test;

namespace {

constexpr int kW = 320, kH = 180;

class ForwardPlusGlTest : public LightingGlTest {
protected:
    ForwardPlusGlTest() : LightingGlTest(kW, kH, true) {}

    FloatImage expectMatchesForward(Camera const& cam, std::string const& where) {
        FloatImage const forward = lighting(lightingSettings(LightingMode::Forward), cam);
        FloatImage const plus = lighting(lightingSettings(LightingMode::ForwardPlus), cam);
        // forward+ adds the same lights as forward at each fragment (every light that can reach it is in
        // its tile's list; the others add zero in forward), in another order: sameSumBound.
        ImageDiff const d = compareRgb(plus, forward, sameSumBound);
        EXPECT_GT(d.meanValue, 0.01) << where << ": the frame should be visibly lit";
        EXPECT_EQ(d.pixelsOver, 0) << where << ": " << describe(d);
        return plus;
    }

    // The coverage counts' first channel (lights in the pixel's tile), over the frame.
    std::vector<float> tileCounts() {
        FloatImage const img = renderer_->readAttachment(Attachment::Coverage);
        std::vector<float> out;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) out.push_back(img.at(x, y, 0));
        return out;
    }
};

}  // namespace

TEST_F(ForwardPlusGlTest, MatchesForwardFromTheTestCamera) {
    expectMatchesForward(camera_, "test camera");
}

TEST_F(ForwardPlusGlTest, MatchesForwardFromTheDefaultSceneCamera) {
    expectMatchesForward(scene_.camera.value_or(Camera{}), "scene camera");
}

TEST_F(ForwardPlusGlTest, MatchesForwardWithTheCameraInsideAVolume) {
    Camera const cam = insideCamera();
    ASSERT_LT(glm::length(cam.position - lights_[0].position), lightRadius(lights_[0]).radius);
    expectMatchesForward(cam, "inside light 0");
}

TEST_F(ForwardPlusGlTest, RunsItsDeclaredPassesAndDrawsTheSceneTwice) {
    FrameStats st;
    lighting(lightingSettings(LightingMode::ForwardPlus), camera_, lights_, &st);
    std::vector<std::string> ran;
    for (PassCalls const& c : st.calls) ran.push_back(c.name);
    EXPECT_EQ(ran, (std::vector<std::string>{"depth_prepass", "light_lists", "forward_shading", "forward", "display"}));
    // The opaque scene drawn once for depth and once shaded; the lists dispatched in between.
    EXPECT_GT(passCalls(st, "depth_prepass").draws, 0u);
    EXPECT_EQ(passCalls(st, "depth_prepass").draws, passCalls(st, "forward_shading").draws);
    EXPECT_GT(passCalls(st, "light_lists").dispatches, 0u);
    EXPECT_EQ(passCalls(st, "light_lists").draws, 0u);
}

TEST_F(ForwardPlusGlTest, CountsTheSameLightsPerTileAsTiled) {
    // Both bin over the same depth (the G-buffer's, or the pre-pass's) and count with the tiled
    // pass's test: the heat views agree tile for tile.
    PipelineSettings s = lightingSettings(LightingMode::Tiled);
    s.view = DebugView::TileLights;
    lighting(s, camera_);
    std::vector<float> const tiled = tileCounts();
    s.mode = LightingMode::ForwardPlus;
    lighting(s, camera_);
    std::vector<float> const plus = tileCounts();
    ASSERT_EQ(plus.size(), tiled.size());
    float most = 0.0f;
    int differ = 0;
    for (std::size_t i = 0; i < plus.size(); ++i) {
        most = std::max(most, plus[i]);
        differ += plus[i] != tiled[i];
    }
    EXPECT_GT(most, 1.0f) << "some tile should list several lights";
    EXPECT_EQ(differ, 0);
    // The heat map of forward+ counts the same lists.
    s.view = DebugView::Heatmap;
    lighting(s, camera_);
    EXPECT_EQ(tileCounts(), plus);
}

// The default scene's glass, seen from its camera through the three panes: the blended pass reads
// the tiles' lists too (its own, binned from the near plane) and gives forward's image.
TEST_F(ForwardPlusGlTest, MatchesForwardWithTheDefaultSceneGlass) {
    Camera const cam = scene_.camera.value_or(Camera{});
    FloatImage const plain = lighting(lightingSettings(LightingMode::Forward), cam);
    SceneData glass = makeDefaultScene({int(lights_.size()), true});
    ASSERT_FALSE(renderer_->setScene(glass));
    FloatImage const withGlass = expectMatchesForward(cam, "scene camera, glass");
    ImageDiff const panes = compareRgb(withGlass, plain, sameSumBound);
    EXPECT_GT(panes.pixelsOver, kW * kH / 20) << "the panes should cover a good part of the frame";
}

// A pane in front of a wall, lit by one light whose sphere reaches the pane but not the wall: the
// opaque lists (binned over the wall's depth) leave it out; the blended surfaces' lists, binned
// from the near plane, keep it, so forward+ lights the pane as forward does.
TEST_F(ForwardPlusGlTest, LightsAPaneALightReachesInFrontOfTheOpaqueDepth) {
    SceneData s = test::floorAndWallScene();
    Material glass;
    glass.name = "test glass";
    glass.baseColorFactor = {0.2f, 0.45f, 0.9f, 0.4f};
    glass.alphaMode = AlphaMode::Blend;
    glass.doubleSided = true;
    s.materials.push_back(glass);
    MeshData pane = makePlane({3.0f, 2.0f});
    pane.material = int(s.materials.size()) - 1;
    s.meshes.push_back(pane);
    s.instances.push_back(
        {int(s.meshes.size()) - 1, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 2.0f, 1.5f)) *
                                       glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1, 0, 0))});
    ASSERT_FALSE(renderer_->setScene(s));
    PointLight l;
    l.position = {0.0f, 2.0f, 1.8f};
    l.color = {1.0f, 1.0f, 1.0f};
    l.intensity = 2.0f;
    l.kc = 1.0f;
    l.kl = 0.0f;
    l.kq = 100.0f;
    float const radius = lightRadius(l).radius;
    ASSERT_GT(radius, 0.5f) << "the sphere should reach the pane, 0.3 units away";
    ASSERT_LT(radius, 1.6f) << "and not the wall, 1.8 units away";
    lights_ = {l};
    Camera const cam = test::lookingAt({0.0f, 2.0f, 6.0f}, {0.0f, 2.0f, 0.0f});
    PipelineSettings s0 = lightingSettings(LightingMode::Forward);
    s0.ambient = glm::vec3(0.2f);
    FloatImage const forward = lighting(s0, cam);
    s0.mode = LightingMode::ForwardPlus;
    FloatImage const plus = lighting(s0, cam);
    ImageDiff const d = compareRgb(plus, forward, sameSumBound);
    EXPECT_EQ(d.pixelsOver, 0) << describe(d);
    // The light shows on the pane: the centre pixel brighter than without it.
    lights_.clear();
    FloatImage const unlit = lighting(s0, cam);
    EXPECT_GT(plus.at(kW / 2, kH / 2, 2), unlit.at(kW / 2, kH / 2, 2) + 0.03f) << "blue, the pane's colour";
}
