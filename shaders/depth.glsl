// Depth linearisation, the same function as linearDepth() in renderer/core/depth.h (see there
// for why it is written this way: nothing cancels near the far plane).
float linearDepth(float windowDepth, float nearPlane, float farPlane) {
    return nearPlane * farPlane / ((1.0 - windowDepth) * farPlane + windowDepth * nearPlane);
}
