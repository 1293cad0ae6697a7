// Forward shading: every light evaluated per fragment while drawing each object (no G-buffer).
// Used by the `forward` lighting mode and for alpha-blended materials after deferred lighting.
#version 330 core
#include "bindings.glsl"
#include "material.glsl"
#include "lighting.glsl"
#include "light_fetch.glsl"
#include "surface_terms.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUV;
in vec4 vTangent;

uniform vec3 uAmbient;
uniform int uLightCount;

out vec4 fragColor;

// Light i where it can add anything: within its radius, or anywhere with the learnopengl shading
// (its attenuation has no window; forward does not cut it, as quad does not).
vec3 shadeNear(int i, SurfacePoint s, vec3 albedo, float spec) {
    vec4 pr = lightTexel(i * 4);
    bool near = distance(pr.xyz, s.p) < pr.w || (uShadingModel == SHADING_LEARNOPENGL && pr.w > 0.0);
    return near ? shadeLight(fetchLight(i), s, albedo, spec) : vec3(0.0);
}

void main() {
    vec4 base = materialBaseColor(vUV);
    if (uAlphaMask && base.a < uAlphaCutoff) discard;
    vec3 n = materialNormal(vNormal, vTangent, vUV, gl_FrontFacing);
    float spec = materialSpecular(vUV);
#ifdef GBUFFER_NO_EMISSIVE_AO
    // The layout (packed) has no room for emission and occlusion: forward shows what deferred does.
    vec3 color = surfaceTerms(uAmbient, base.rgb, 1.0, vec3(0.0));
#else
    vec3 color = surfaceTerms(uAmbient, base.rgb, materialOcclusion(vUV), materialEmissive(vUV));
#endif
    color += shadeGlobalLights(vWorldPos, n, base.rgb, spec);  // directional lights
    // Every light in index order, LIGHTS_PER_ITERATION at a time (light_fetch.glsl says why).
    SurfacePoint s = surfacePoint(vWorldPos, n);  // the eye direction once, not once per light
#define ADD(j) color += shadeNear(j, s, base.rgb, spec)
    FOR_EVERY_LIGHT(uLightCount, ADD)
#undef ADD
    fragColor = vec4(color, base.a);
}
