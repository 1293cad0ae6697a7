// Editor camera control: orbit around a target, fly with WASD, frame the scene. Pure math, no GL.
#pragma once

#include "core/camera.h"
#include "scene/scene_data.h"

#include <glm/glm.hpp>

namespace gbl::ui {

// What the camera orbits around and how fast it moves; the Camera itself holds position and
// orientation, so a session only needs the Camera plus the target.
struct CameraRig {
    glm::vec3 target{0.0f};
    float moveSpeed = 6.0f;        // world units per second for WASD
    float degreesPerPixel = 0.3f;  // mouse look and orbit sensitivity
};

// One frame of user input, gathered by the window loop from the mouse over the viewport and
// the keyboard. Drags are in pixels since the last frame.
struct CameraInput {
    glm::vec2 orbitDrag{0.0f};  // left drag: rotate around the target
    glm::vec2 lookDrag{0.0f};   // right drag: turn the camera in place (fly)
    glm::vec2 panDrag{0.0f};    // middle drag: slide camera and target in the view plane
    float dolly = 0.0f;         // mouse wheel notches, positive = towards the target
    glm::vec3 move{0.0f};       // WASD/QE: x right, y up, z forward, each -1..1
    bool fast = false;          // shift held
    float dt = 0.0f;            // seconds since the last frame
    float viewportHeight = 1.0f;
};

// Applies one frame of input. Orbiting keeps the distance to the target; looking and moving
// carry the target along so switching between the two never jumps.
void applyCameraInput(CameraRig& rig, Camera& camera, CameraInput const& input);

// Places the camera so the bounding sphere of `bounds` fills the view, looking at its centre
// from the camera's current direction.
void frameBounds(CameraRig& rig, Camera& camera, Bounds const& bounds);

// Orbit target for a camera that arrives from elsewhere (scene suggestion, session file):
// the point `distance` ahead of it.
void resetTargetAhead(CameraRig& rig, Camera const& camera, float distance);

}  // namespace gbl::ui
