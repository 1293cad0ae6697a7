// Home view, the file's cameras and F: a light is framed at the centre of the view, an enclosing scene from inside.
#include "model/camera_views.h"

#include <gtest/gtest.h>

using namespace gbl;
using namespace gbl::ui;

namespace {
Bounds const kCourtyard{{-12, 0, -12}, {12, 8, 12}};

// The point ends up straight ahead of the camera.
void expectAhead(Camera const& c, glm::vec3 p) {
    glm::vec3 const d = glm::normalize(p - c.position);
    EXPECT_GT(glm::dot(d, c.forward()), 0.9999f);
}
}  // namespace

TEST(CameraViews, HomeIsTheSuggestedCameraOrTheFramedScene) {
    Camera suggested;
    suggested.position = {0, 5, 11.5f};
    suggested.lookAt({0, 1, -2});
    CameraView const home = homeView(suggested, kCourtyard, CameraRig{});
    EXPECT_EQ(home.camera.position, suggested.position);
    EXPECT_FLOAT_EQ(home.camera.yawDegrees, suggested.yawDegrees);
    expectAhead(home.camera, home.rig.target);

    CameraView const framed = homeView(std::nullopt, kCourtyard, CameraRig{});
    EXPECT_EQ(framed.rig.target, kCourtyard.center());
    EXPECT_FALSE(insideBounds(framed.camera.position, kCourtyard)) << "framing the whole box is from outside";
}

TEST(CameraViews, FramingALightPutsItAheadAtAUsefulDistance) {
    CameraRig rig;
    Camera camera;
    glm::vec3 const light{3, 2, -4};
    frameLight(rig, camera, light, 10.0f, kCourtyard);
    expectAhead(camera, light);
    EXPECT_NEAR(glm::length(light - camera.position), 5.0f, 1e-4f) << "half the radius";
    EXPECT_EQ(rig.target, light);
    frameLight(rig, camera, light, 500.0f, kCourtyard);
    EXPECT_NEAR(glm::length(light - camera.position), kCourtyard.radius() / 3.0f, 1e-3f) << "capped by the scene";
    frameLight(rig, camera, light, 0.1f, kCourtyard);
    EXPECT_NEAR(glm::length(light - camera.position), 1.0f, 1e-4f) << "never closer than 1";
}

TEST(CameraViews, NothingSelectedShowsAnEnclosingSceneFromInside) {
    Camera suggested;
    suggested.position = {0, 5, 11.5f};
    suggested.lookAt({0, 1, -2});
    CameraView const home = homeView(suggested, kCourtyard, CameraRig{});
    CameraRig rig;
    Camera camera;
    camera.position = {100, 100, 100};
    frameNothingSelected(rig, camera, home, kCourtyard);
    EXPECT_TRUE(insideBounds(camera.position, kCourtyard));
    EXPECT_EQ(camera.position, suggested.position);

    // A small object seen from outside: framed as a whole.
    Bounds const duck{{-1, 0, -1}, {1, 1.5f, 1}};
    CameraView const outside = homeView(std::nullopt, duck, CameraRig{});
    frameNothingSelected(rig, camera, outside, duck);
    EXPECT_EQ(rig.target, duck.center());
    expectAhead(camera, duck.center());
}

TEST(CameraViews, TheFilesCamerasAreOfferedWhereTheFilePutsThem) {
    Camera overview;
    overview.position = {20, 10, 0};
    overview.lookAt({0, 4, 0});
    overview.fovYDegrees = 40.0f;
    Camera inside;
    inside.position = kCourtyard.center();
    CameraRig rig;
    rig.moveSpeed = 2.5f;  // the user's rig settings carry over
    std::vector<NamedView> const views =
        sceneCameraViews({{"overview", overview, 1.5f}, {"camera 1", inside, 0.0f}}, kCourtyard, rig);
    ASSERT_EQ(views.size(), 2u);
    EXPECT_EQ(views[0].name, "overview");
    EXPECT_EQ(views[0].view.camera.position, overview.position);
    EXPECT_FLOAT_EQ(views[0].view.camera.fovYDegrees, 40.0f);
    EXPECT_FLOAT_EQ(views[0].view.rig.moveSpeed, 2.5f);
    // The orbit target is straight ahead, as far as the scene's centre.
    expectAhead(views[0].view.camera, views[0].view.rig.target);
    EXPECT_NEAR(glm::length(views[0].view.rig.target - overview.position),
                glm::length(kCourtyard.center() - overview.position), 1e-4f);
    // A camera at the centre itself still orbits a point ahead of it.
    EXPECT_GT(glm::length(views[1].view.rig.target - inside.position), 0.0f);
    expectAhead(views[1].view.camera, views[1].view.rig.target);
    EXPECT_TRUE(sceneCameraViews({}, kCourtyard, rig).empty());
}
