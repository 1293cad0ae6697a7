// Full-screen lighting: every pixel loops over every light (the first deferred lighting pass).
// msaa variants (docs/msaa.md), GBL_MSAA_SAMPLES n with a multisampled G-buffer: every sample lit
// and the results averaged (per-sample; the edges strategy's complex pixels), or with
// GBL_MSAA_SAMPLE0 sample 0 alone (the edges strategy's simple pixels); GBL_MSAA_EDGES makes the
// detection pass instead (msaa_edges.glsl), which reads the samples through the same functions.
#version 330 core
#include "bindings.glsl"
#include "lighting.glsl"
#include "light_fetch.glsl"
#include "gbuffer_read.glsl"
#include "surface_terms.glsl"
#include "light_accumulation.glsl"
#ifdef GBL_MSAA_EDGES
#include "msaa_edges.glsl"
#endif

uniform vec3 uAmbient;
uniform int uLightCount;

layout(location = 0) out vec4 fragColor;     // the lit value; split: diffuse light
layout(location = 1) out vec4 fragSpecular;  // split: specular light (no attachment in single frames)

// The lit value of the surface at px (of sample gSample in the msaa variants), and its specular light.
vec4 shadePixel(ivec2 px, out vec4 specular) {
    vec3 pos;
    specular = vec4(0.0);
    if (!gbufferPosition(px, pos)) return vec4(0.0);  // background: nothing was drawn
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
    specular = vec4(sum.specular, 1.0);
    return accumulationTarget0(sum, surface, as.rgb);
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
#if defined(GBL_MSAA_EDGES)
    if (!msaaComplexPixel(px)) discard;  // simple: left unmarked
    fragColor = vec4(1.0);
    fragSpecular = vec4(0.0);
#elif defined(GBL_MSAA_SAMPLES) && !defined(GBL_MSAA_SAMPLE0)
    vec4 lit = vec4(0.0), spec = vec4(0.0);
    for (int i = 0; i < GBL_MSAA_SAMPLES; ++i) {
        gSample = i;
        vec4 sp;
        lit += shadePixel(px, sp);
        spec += sp;
    }
    fragColor = lit / float(GBL_MSAA_SAMPLES);
    fragSpecular = spec / float(GBL_MSAA_SAMPLES);
#else
#ifdef GBL_MSAA_SAMPLE0
    gSample = -1;  // lit once, at the pixel's centre (gbuffer_read.glsl)
#endif
    fragColor = shadePixel(px, fragSpecular);
#endif
}
