// prepass (deferred lighting, docs/deferred_lighting.md): every light at each pixel of the thin
// G-buffer, summed into two targets: diffuse light (N.L * attenuation * colour) and specular light
// ((N.H)^exponent * attenuation * colour). The thin G-buffer holds no material, so the specular
// intensity is 1 here; prepass_shade.frag multiplies the sums by albedo and intensity. Built with
// GBL_SHININESS_PER_PIXEL: the exponent is the one the pixel stored (lighting.glsl). With
// `prepass_lights: volumes` it runs with uLightCount 0 before the volumes: the directional lights alone.
#version 330 core
#include "bindings.glsl"
#include "lighting.glsl"
#include "light_fetch.glsl"
#include "light_accumulation.glsl"
#include "prepass_surface.glsl"

uniform int uLightCount;

layout(location = 0) out vec4 fragDiffuse;
layout(location = 1) out vec4 fragSpecular;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    fragDiffuse = vec4(0.0);
    fragSpecular = vec4(0.0);
    SurfacePoint s;
    if (!prepassSurface(px, s)) return;
    LightSum sum = noLight();
    accumulateGlobalLights(sum, s, 1.0);
    // Every light in index order, LIGHTS_PER_ITERATION at a time, as the quad pass does.
#define ADD(j) accumulateListedLight(sum, j, true, s, 1.0)
    FOR_EVERY_LIGHT(uLightCount, ADD)
#undef ADD
    fragDiffuse = vec4(sum.diffuse, 1.0);
    fragSpecular = vec4(sum.specular, 1.0);
}
