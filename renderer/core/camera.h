// Perspective camera: yaw/pitch around a position, shared by renderer, editor and sessions.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <optional>

namespace gbl {

struct Camera {
    glm::vec3 position{0.0f, 3.0f, 12.0f};
    float yawDegrees = -90.0f;  // -90 looks down -Z
    float pitchDegrees = -10.0f;
    float fovYDegrees = 60.0f;
    float nearPlane = 0.1f;
    float farPlane = 200.0f;
    // Another program's matrices, for a camera fixed to an imported G-buffer's frame
    // (import/relight_frame.h): view() and projection() return them as given, so picking, the pixel
    // inspector and why-this-value use that frame's exact transform, roll and off-centre
    // projections included. The fields above then hold the nearest yaw/pitch camera, for what
    // reads angles. Unset for every camera the editor moves.
    std::optional<glm::mat4> fixedView;
    std::optional<glm::mat4> fixedProjection;

    glm::vec3 forward() const {
        float const yaw = glm::radians(yawDegrees), pitch = glm::radians(pitchDegrees);
        return glm::normalize(
            glm::vec3(std::cos(yaw) * std::cos(pitch), std::sin(pitch), std::sin(yaw) * std::cos(pitch)));
    }
    glm::vec3 right() const { return glm::normalize(glm::cross(forward(), glm::vec3(0, 1, 0))); }
    glm::vec3 up() const { return glm::cross(right(), forward()); }

    glm::mat4 view() const {
        if (fixedView) return *fixedView;
        return glm::lookAt(position, position + forward(), glm::vec3(0, 1, 0));
    }
    // `aspect` is width / height of the frame; a fixed projection is the frame's own, as given.
    glm::mat4 projection(float aspect) const {
        if (fixedProjection) return *fixedProjection;
        return glm::perspective(glm::radians(fovYDegrees), aspect, nearPlane, farPlane);
    }

    // Points the camera at target from its current position.
    void lookAt(glm::vec3 target) {
        glm::vec3 const d = glm::normalize(target - position);
        pitchDegrees = glm::degrees(std::asin(glm::clamp(d.y, -1.0f, 1.0f)));
        yawDegrees = glm::degrees(std::atan2(d.z, d.x));
    }
};

}  // namespace gbl
