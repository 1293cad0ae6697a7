// Depth linearisation: window-space depth back to distance in front of the camera. Pure math;
// shaders/depth.glsl is the same function for the shaders.
#pragma once

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

}  // namespace gbl
