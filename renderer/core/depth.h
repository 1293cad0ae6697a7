// Depth linearisation: window-space depth back to distance in front of the camera. Pure math;
// shaders/depth.glsl is the same function for the shaders.
#pragma once

#include <glm/glm.hpp>

namespace gbl {

// Positive distance in front of the camera (-z in view space) of a window-space depth d in
// [0, 1] written with glm::perspective (OpenGL clip space, NDC z in [-1, 1], default depth range).
// With z_ndc = 2d - 1 the textbook form is 2nf / ((f + n) - z_ndc (f - n)) = nf / (f - d (f - n)).
// Both subtract two nearly equal numbers near the far plane (d -> 1: f - d (f - n) -> n), so a
// float loses about log2(f / n) bits there. Written as nf / ((1 - d) f + d n) nothing cancels:
// 1 - d is exact for d in [0.5, 1] and the two products are positive, so the result is within
// a few float roundings of the exact value for every d (tests/depth_test.cpp bounds it).
inline float linearDepth(float windowDepth, float nearPlane, float farPlane) {
    return nearPlane * farPlane / ((1.0f - windowDepth) * farPlane + windowDepth * nearPlane);
}

// The world position a window-space depth d at pixel `pixel` (GL's bottom-left origin, the
// pixel's centre) of a width x height frame stands for: unprojected through the inverse
// view-projection, as the layouts that store no position rebuild it (shaders/gbuffer_read.glsl).
inline glm::vec3 worldFromDepth(glm::mat4 const& inverseViewProj, glm::ivec2 pixel, glm::ivec2 size, float d) {
    glm::vec4 const ndc((float(pixel.x) + 0.5f) / float(size.x) * 2.0f - 1.0f,
                        (float(pixel.y) + 0.5f) / float(size.y) * 2.0f - 1.0f, d * 2.0f - 1.0f, 1.0f);
    glm::vec4 const world = inverseViewProj * ndc;
    return glm::vec3(world) / world.w;
}

}  // namespace gbl
