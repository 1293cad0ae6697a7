// Ray construction and ray-vs-box tests for selecting lights by clicking their cubes.
#include "model/light_pick.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gbl::ui {

Ray cameraRay(Camera const& camera, glm::vec2 pixel, glm::vec2 viewportSize) {
    glm::vec2 const size = glm::max(viewportSize, glm::vec2(1.0f));
    // Pixel centre to normalised device coordinates; y flips because the mouse counts down.
    glm::vec2 const ndc((pixel.x + 0.5f) / size.x * 2.0f - 1.0f, 1.0f - (pixel.y + 0.5f) / size.y * 2.0f);
    float const tanHalf = std::tan(glm::radians(camera.fovYDegrees) * 0.5f);
    float const aspect = size.x / size.y;
    glm::vec3 const dir =
        camera.forward() + camera.right() * (ndc.x * tanHalf * aspect) + camera.up() * (ndc.y * tanHalf);
    return {camera.position, glm::normalize(dir)};
}

std::optional<float> rayBoxDistance(Ray const& ray, glm::vec3 boxMin, glm::vec3 boxMax) {
    float tNear = 0.0f;
    float tFar = std::numeric_limits<float>::max();
    for (int axis = 0; axis < 3; ++axis) {
        float const o = ray.origin[axis], d = ray.direction[axis];
        if (std::abs(d) < 1e-12f) {
            // Parallel to this slab: inside it or never.
            if (o < boxMin[axis] || o > boxMax[axis]) return std::nullopt;
            continue;
        }
        float t0 = (boxMin[axis] - o) / d, t1 = (boxMax[axis] - o) / d;
        if (t0 > t1) std::swap(t0, t1);
        tNear = std::max(tNear, t0);
        tFar = std::min(tFar, t1);
        if (tNear > tFar) return std::nullopt;
    }
    return tNear;
}

int pickLight(Ray const& ray, std::span<PointLight const> lights, float cubeHalfExtent, float maxDistance) {
    int best = -1;
    float bestT = maxDistance;
    glm::vec3 const h(cubeHalfExtent);
    for (std::size_t i = 0; i < lights.size(); ++i) {
        auto const t = rayBoxDistance(ray, lights[i].position - h, lights[i].position + h);
        if (t && *t < bestT) {
            bestT = *t;
            best = int(i);
        }
    }
    return best;
}

}  // namespace gbl::ui
