// A screen tile's view-space frustum side planes, shared by tiled and clustered list building
// (renderer/core/tile_math.h is the CPU twin). Needs uniform mat4 uInverseProjection.
#ifndef GBL_TILE_FRUSTUM_GLSL
#define GBL_TILE_FRUSTUM_GLSL
uniform mat4 uInverseProjection;

vec3 unprojectFar(vec2 ndc) {
    vec4 v = uInverseProjection * vec4(ndc, 1.0, 1.0);
    return v.xyz / v.w;
}

vec4 sidePlane(vec3 a, vec3 b, vec3 inside) {
    vec3 n = normalize(cross(a, b));
    if (dot(n, inside) < 0.0) n = -n;
    return vec4(n, 0.0);
}
#endif
