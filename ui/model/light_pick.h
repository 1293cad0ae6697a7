// Picking a light cube under the mouse: a camera ray against each light's cube, on the CPU.
#pragma once

#include "core/camera.h"
#include "core/point_light.h"

#include <glm/glm.hpp>

#include <optional>
#include <span>

namespace gbl::ui {

struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // unit length
};

// Ray through the centre of pixel (x, y), origin at the top-left as the mouse reports it.
Ray cameraRay(Camera const& camera, glm::vec2 pixel, glm::vec2 viewportSize);

// Distance along the ray to an axis-aligned box (slab test), nullopt when it misses or the
// box is entirely behind the origin. A ray starting inside the box hits at 0.
std::optional<float> rayBoxDistance(Ray const& ray, glm::vec3 boxMin, glm::vec3 boxMax);

// Index of the nearest light whose cube (centre = light position, half extent as drawn by the
// renderer) the ray hits before maxDistance, or -1.
int pickLight(Ray const& ray, std::span<PointLight const> lights, float cubeHalfExtent, float maxDistance);

}  // namespace gbl::ui
