// Coverage for the modes that evaluate every light at every pixel (quad, forward): x = lights
// evaluated, y = lights that actually reached the surface.
#version 330 core
#include "bindings.glsl"
#include "lighting.glsl"
#include "light_fetch.glsl"
#include "gbuffer_read.glsl"

uniform int uLightCount;
out vec4 fragColor;

// 1 where light i reaches the surface point and lights it, else 0.
float litBy(int i, SurfacePoint s) {
    return any(greaterThan(shadeLight(fetchLight(i), s, vec3(1.0), 1.0), vec3(0.0))) ? 1.0 : 0.0;
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec3 pos;
    if (!gbufferPosition(px, pos)) { fragColor = vec4(0.0); return; }
    vec3 n = gbufferNormal(px);
    SurfacePoint s = surfacePoint(pos, n);
    float lit = 0.0;
    // LIGHTS_PER_ITERATION lights an iteration (light_fetch.glsl says why).
#define ADD(j) lit += litBy(j, s)
    FOR_EVERY_LIGHT(uLightCount, ADD)
#undef ADD
    // Directional lights (radius 0 above, so never counted there) light every surface facing them.
    for (int k = 0; k < uDirectionalCount; ++k)
        if (any(greaterThan(shadeDirectional(fetchLight(uDirectionalLights[k]), pos, n, vec3(1.0), 1.0), vec3(0.0))))
            lit += 1.0;
    fragColor = vec4(float(uLightCount), lit, 0.0, 0.0);
}
