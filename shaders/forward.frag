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
    for (int i = 0; i < uLightCount; ++i) {
        vec4 pr = texelFetch(uLights, i * 4);
        if (distance(pr.xyz, vWorldPos) >= pr.w) continue;
        color += shadeLight(fetchLight(i), vWorldPos, n, base.rgb, spec);
    }
    fragColor = vec4(color, base.a);
}
