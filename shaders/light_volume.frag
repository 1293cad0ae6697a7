// Light volumes: shades the G-buffer pixel under each volume fragment with that one light,
// added to the HDR target by blending. With COVERAGE defined it instead counts, per pixel, the
// volume fragments that ran (x) and the ones whose light actually reached the surface (y). msaa
// variants as the quad pass's (lighting_quad.frag): GBL_MSAA_SAMPLES n lights every sample and
// averages, adding GBL_MSAA_SAMPLE0 lights the pixel once at its centre. With PREPASS_LIGHTS
// (prepass's light pass with `prepass_lights: volumes`, docs/deferred_lighting.md) it reads the thin
// G-buffer instead and adds the light's diffuse and specular light, specular intensity 1, into the two
// light targets, as prepass_light.frag sums them.
#version 330 core
#include "bindings.glsl"
#include "lighting.glsl"
#include "light_fetch.glsl"
#ifdef PREPASS_LIGHTS
#include "prepass_surface.glsl"
#else
#include "gbuffer_read.glsl"
#endif
#include "light_accumulation.glsl"

flat in int vLight;
layout(location = 0) out vec4 fragColor;
#ifndef COVERAGE
layout(location = 1) out vec4 fragSpecular;  // split: specular light (no attachment in single frames)
#endif

#ifdef COVERAGE
// x: the fragment ran; y: the light reached the surface.
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec3 pos;
    bool drawn = gbufferPosition(px, pos);
    vec4 positionRadius = lightTexel(vLight * 4);
    bool inside = drawn && distance(positionRadius.xyz, pos) < positionRadius.w;
    vec3 lit = inside ? shadeLight(fetchLight(vLight), pos, gbufferNormal(px), vec3(1.0), 1.0) : vec3(0.0);
    fragColor = vec4(1.0, any(greaterThan(lit, vec3(0.0))) ? 1.0 : 0.0, 0.0, 0.0);
}
#elif defined(PREPASS_LIGHTS)
// Adding zero instead of discarding, as below.
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    SurfacePoint surface;
    bool drawn = prepassSurface(px, surface);
    vec4 positionRadius = lightTexel(vLight * 4);
    fragColor = fragSpecular = vec4(0.0);
    if (!drawn || distance(positionRadius.xyz, surface.p) >= positionRadius.w) return;
    LightSum sum = noLight();
    accumulateLight(sum, fetchLight(vLight), surface, 1.0);
    fragColor = vec4(sum.diffuse, 0.0);
    fragSpecular = vec4(sum.specular, 0.0);
}
#else
// The light's term at the surface of px (of sample gSample in the msaa variants), and its specular
// light. The mesh is a little larger than the light's sphere: surfaces between the two, and the
// background, get nothing (the same zero the other modes compute past the radius). The test needs
// only the first texel of the light, so most rejected fragments stop here.
vec4 shadeVolumePixel(ivec2 px, out vec4 specular) {
    specular = vec4(0.0);
    vec3 pos;
    bool drawn = gbufferPosition(px, pos);
    vec4 positionRadius = lightTexel(vLight * 4);
    if (!drawn || distance(positionRadius.xyz, pos) >= positionRadius.w) return vec4(0.0);
    vec4 as = gbufferAlbedoSpec(px);
    LightSum sum = noLight();
    accumulateLight(sum, fetchLight(vLight), surfacePoint(pos, gbufferNormal(px)), as.a);
    specular = vec4(sum.specular, 0.0);
    // Blended additively: the surface terms came with the full-screen pass before the volumes.
    return vec4(accumulationTarget0(sum, vec3(0.0), as.rgb).rgb, 0.0);
}

// Adding zero instead of discarding: a shader that may discard makes llvmpipe (and many GPUs) run it
// before the depth test, and in the stencil cull mode a discarded fragment would skip the stencil
// reset and leave its mark for the next light.
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
#if defined(GBL_MSAA_SAMPLES) && !defined(GBL_MSAA_SAMPLE0)
    // msaa (docs/msaa.md): every sample lit and the results averaged, into the single-sample lit image.
    vec4 lit = vec4(0.0), spec = vec4(0.0);
    for (int i = 0; i < GBL_MSAA_SAMPLES; ++i) {
        gSample = i;
        vec4 sp;
        lit += shadeVolumePixel(px, sp);
        spec += sp;
    }
    fragColor = lit / float(GBL_MSAA_SAMPLES);
    fragSpecular = spec / float(GBL_MSAA_SAMPLES);
#else
#ifdef GBL_MSAA_SAMPLE0
    gSample = -1;  // the edges strategy's simple pixels: lit once, at the centre (gbuffer_read.glsl)
#endif
    fragColor = shadeVolumePixel(px, fragSpecular);
#endif
}
#endif
