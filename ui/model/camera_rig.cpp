// Orbit, fly and framing for the editor camera.
#include "model/camera_rig.h"

#include <algorithm>
#include <cmath>

namespace gbl::ui {

namespace {
// Just short of straight up/down, where yaw stops meaning anything and lookAt degenerates.
constexpr float kMaxPitch = 89.0f;
constexpr float kMinDistance = 0.05f;

void turn(Camera& camera, glm::vec2 dragPixels, float degreesPerPixel) {
    camera.yawDegrees += dragPixels.x * degreesPerPixel;
    camera.pitchDegrees = std::clamp(camera.pitchDegrees - dragPixels.y * degreesPerPixel, -kMaxPitch, kMaxPitch);
    camera.yawDegrees = std::remainder(camera.yawDegrees, 360.0f);
}
}  // namespace

void applyCameraInput(CameraRig& rig, Camera& camera, CameraInput const& input) {
    float distance = std::max(glm::length(rig.target - camera.position), kMinDistance);

    if (input.orbitDrag != glm::vec2(0.0f)) {
        turn(camera, input.orbitDrag, rig.degreesPerPixel);
        camera.position = rig.target - camera.forward() * distance;
    }
    if (input.lookDrag != glm::vec2(0.0f)) {
        turn(camera, input.lookDrag, rig.degreesPerPixel);
        rig.target = camera.position + camera.forward() * distance;
    }
    if (input.panDrag != glm::vec2(0.0f)) {
        // One pixel of drag moves the target by one pixel's worth of world at its distance.
        float const worldPerPixel =
            2.0f * distance * std::tan(glm::radians(camera.fovYDegrees) * 0.5f) / std::max(input.viewportHeight, 1.0f);
        glm::vec3 const shift = (-camera.right() * input.panDrag.x + camera.up() * input.panDrag.y) * worldPerPixel;
        camera.position += shift;
        rig.target += shift;
    }
    if (input.dolly != 0.0f) {
        // Each notch covers a fixed fraction of the remaining distance, so zooming never passes
        // the target and feels the same near and far.
        distance = std::max(distance * std::pow(0.85f, input.dolly), kMinDistance);
        camera.position = rig.target - camera.forward() * distance;
    }
    if (input.move != glm::vec3(0.0f) && input.dt > 0.0f) {
        float const speed = rig.moveSpeed * (input.fast ? 4.0f : 1.0f) * input.dt;
        glm::vec3 const step =
            (camera.right() * input.move.x + glm::vec3(0, 1, 0) * input.move.y + camera.forward() * input.move.z) *
            speed;
        camera.position += step;
        rig.target += step;
    }
}

void frameBounds(CameraRig& rig, Camera& camera, Bounds const& bounds) {
    float const radius = std::max(bounds.radius(), 0.01f);
    float const halfFov = glm::radians(camera.fovYDegrees) * 0.5f;
    // Distance at which a sphere of this radius touches the top and bottom of the view; the
    // horizontal field is wider in a landscape viewport so it fits there too.
    float const distance = radius / std::sin(halfFov) * 1.05f;
    rig.target = bounds.center();
    camera.position = rig.target - camera.forward() * distance;
    // Keep the whole sphere between the clip planes.
    camera.farPlane = std::max(camera.farPlane, distance + radius * 2.0f);
}

void resetTargetAhead(CameraRig& rig, Camera const& camera, float distance) {
    rig.target = camera.position + camera.forward() * std::max(distance, kMinDistance);
}

}  // namespace gbl::ui
