// Editor camera control: orbit keeps the distance, look keeps the position, framing fits the scene.
#include "model/camera_rig.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

using namespace gbl;
using namespace gbl::ui;

namespace {
// Float round-off in a handful of trig calls on values of order 10; far below anything visible.
constexpr float kEps = 1e-4f;

Camera cameraLookingAt(glm::vec3 position, glm::vec3 target) {
    Camera c;
    c.position = position;
    c.lookAt(target);
    return c;
}
}  // namespace

TEST(UiCameraRig, OrbitKeepsDistanceAndTarget) {
    CameraRig rig;
    rig.target = glm::vec3(1, 2, 3);
    Camera cam = cameraLookingAt({1, 4, 13}, rig.target);
    float const before = glm::length(cam.position - rig.target);
    CameraInput in;
    in.orbitDrag = {120.0f, -40.0f};
    applyCameraInput(rig, cam, in);
    EXPECT_NEAR(glm::length(cam.position - rig.target), before, kEps);
    EXPECT_EQ(rig.target, glm::vec3(1, 2, 3));
    // Still looking at the target after orbiting.
    EXPECT_NEAR(glm::dot(cam.forward(), glm::normalize(rig.target - cam.position)), 1.0f, kEps);
    EXPECT_NE(cam.position, glm::vec3(1, 4, 13));
}

TEST(UiCameraRig, LookTurnsInPlaceAndCarriesTheTarget) {
    CameraRig rig;
    Camera cam = cameraLookingAt({0, 2, 10}, {0, 2, 0});
    rig.target = {0, 2, 0};
    CameraInput in;
    in.lookDrag = {300.0f, 0.0f};  // 90 degrees at 0.3 degrees per pixel
    applyCameraInput(rig, cam, in);
    EXPECT_EQ(cam.position, glm::vec3(0, 2, 10));
    EXPECT_NEAR(cam.yawDegrees, 0.0f, kEps);  // from -90 (looking down -Z) to 0 (looking down +X)
    EXPECT_NEAR(glm::length(rig.target - cam.position), 10.0f, kEps);
    EXPECT_NEAR(glm::dot(glm::normalize(rig.target - cam.position), cam.forward()), 1.0f, kEps);
}

TEST(UiCameraRig, PitchStopsShortOfStraightUp) {
    CameraRig rig;
    Camera cam;
    CameraInput in;
    in.lookDrag = {0.0f, -100000.0f};
    applyCameraInput(rig, cam, in);
    EXPECT_LE(cam.pitchDegrees, 89.0f);
    EXPECT_GT(cam.pitchDegrees, 88.0f);
    EXPECT_TRUE(std::isfinite(cam.forward().x));
}

TEST(UiCameraRig, DollyApproachesButNeverPassesTheTarget) {
    CameraRig rig;
    Camera cam = cameraLookingAt({0, 0, 10}, {0, 0, 0});
    CameraInput in;
    in.dolly = 1.0f;
    applyCameraInput(rig, cam, in);
    EXPECT_NEAR(cam.position.z, 8.5f, kEps);  // one notch keeps 85% of the distance
    in.dolly = 200.0f;
    applyCameraInput(rig, cam, in);
    EXPECT_GT(cam.position.z, 0.0f);
}

TEST(UiCameraRig, MoveForwardFollowsTheViewAndSpeed) {
    CameraRig rig;
    rig.moveSpeed = 2.0f;
    Camera cam = cameraLookingAt({0, 0, 10}, {0, 0, 0});
    rig.target = {0, 0, 0};
    CameraInput in;
    in.move = {0, 0, 1};
    in.dt = 0.5f;
    applyCameraInput(rig, cam, in);
    EXPECT_NEAR(cam.position.z, 9.0f, kEps);
    EXPECT_NEAR(rig.target.z, -1.0f, kEps);
    in.fast = true;  // shift: four times faster
    applyCameraInput(rig, cam, in);
    EXPECT_NEAR(cam.position.z, 5.0f, kEps);
}

TEST(UiCameraRig, PanMovesTargetAcrossTheView) {
    CameraRig rig;
    Camera cam = cameraLookingAt({0, 0, 10}, {0, 0, 0});
    CameraInput in;
    in.panDrag = {100.0f, 0.0f};
    in.viewportHeight = 500.0f;
    applyCameraInput(rig, cam, in);
    // Dragging right moves the scene right, so the camera and target move left (-X here).
    EXPECT_LT(rig.target.x, 0.0f);
    EXPECT_NEAR(rig.target.x, cam.position.x, kEps);
    EXPECT_NEAR(rig.target.z, 0.0f, kEps);
    // 100 of 500 pixels at distance 10 with a 60 degree field: 2*10*tan(30deg)/5.
    EXPECT_NEAR(rig.target.x, -2.0f * 10.0f * std::tan(glm::radians(30.0f)) / 5.0f, 1e-3f);
}

TEST(UiCameraRig, FramingPutsEveryCornerOfTheBoundsInView) {
    Bounds b{{-16, 0, -16}, {16, 10, 16}};
    CameraRig rig;
    Camera cam = cameraLookingAt({40, 30, 50}, {0, 0, 0});
    frameBounds(rig, cam, b);
    EXPECT_NEAR(glm::length(rig.target - b.center()), 0.0f, kEps);
    float const aspect = 16.0f / 9.0f;
    glm::mat4 const vp = cam.projection(aspect) * cam.view();
    for (int i = 0; i < 8; ++i) {
        glm::vec3 const corner((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
        glm::vec4 const clip = vp * glm::vec4(corner, 1.0f);
        ASSERT_GT(clip.w, 0.0f);
        glm::vec3 const ndc = glm::vec3(clip) / clip.w;
        EXPECT_LE(std::abs(ndc.x), 1.0f) << "corner " << i;
        EXPECT_LE(std::abs(ndc.y), 1.0f) << "corner " << i;
        EXPECT_LE(std::abs(ndc.z), 1.0f) << "corner " << i << " is clipped by near/far";
    }
}
