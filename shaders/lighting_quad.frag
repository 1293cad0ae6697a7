// Full-screen lighting: every pixel loops over every light (the first deferred lighting pass).
#version 330 core
#include "bindings.glsl"
#include "lighting.glsl"
#include "light_fetch.glsl"
#include "gbuffer_read.glsl"
#include "surface_terms.glsl"
#include "light_accumulation.glsl"

uniform vec3 uAmbient;
uniform int uLightCount;

layout(location = 0) out vec4 fragColor;     // the lit value; split: diffuse light
layout(location = 1) out vec4 fragSpecular;  // split: specular light (no attachment in single frames)

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec3 pos;
    if (!gbufferPosition(px, pos)) {  // background: nothing was drawn
        fragColor = fragSpecular = vec4(0.0);
        return;
    }
    vec3 n = gbufferNormal(px);
    vec4 as = gbufferAlbedoSpec(px);
    vec4 ea = gbufferEmissiveAo(px);
    vec3 surface = surfaceTerms(uAmbient, as.rgb, ea.a, ea.rgb);
    SurfacePoint s = surfacePoint(pos, n);
    LightSum sum = noLight();
    accumulateGlobalLights(sum, s, as.a);  // directional lights: no volume, every pixel
    // Every light in index order, LIGHTS_PER_ITERATION at a time (light_fetch.glsl says why).
#define ADD(j) accumulateListedLight(sum, j, true, s, as.a)
    FOR_EVERY_LIGHT(uLightCount, ADD)
#undef ADD
    fragColor = accumulationTarget0(sum, surface, as.rgb);
    fragSpecular = vec4(sum.specular, 1.0);
}
