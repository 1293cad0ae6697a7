// Light volumes: shades the G-buffer pixel under each volume fragment with that one light,
// added to the HDR target by blending. With COVERAGE defined it instead counts, per pixel, the
// volume fragments that ran (x) and the ones whose light actually reached the surface (y).
// With PREPASS_LIGHTS (prepass's light pass with `prepass_lights: volumes`, docs/deferred_lighting.md)
// it reads the thin G-buffer instead and adds the light's diffuse and specular light, specular
// intensity 1, into the two light targets, as prepass_light.frag sums them.
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
#ifdef GBL_MSAA_SAMPLES
// msaa volumes (docs/msaa.md): the sample lit, the one the draw's sample mask writes, or -1 for the
// simple pixels of the edges strategy, lit once at the centre and written to every sample.
uniform int uSample;
#endif
layout(location = 0) out vec4 fragColor;
#ifndef COVERAGE
layout(location = 1) out vec4 fragSpecular;  // split: specular light (no attachment in single frames)
#endif

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
#ifdef GBL_MSAA_SAMPLES
    gSample = uSample;
#endif
    vec3 pos;
#ifdef PREPASS_LIGHTS
    SurfacePoint surface;
    bool drawn = prepassSurface(px, surface);
    pos = surface.p;
#else
    bool drawn = gbufferPosition(px, pos);
#endif
    // The mesh is a little larger than the light's sphere: surfaces between the two, and the
    // background, get nothing (the same zero the other modes compute past the radius). The
    // test needs only the first texel of the light, so most rejected fragments stop here.
    vec4 positionRadius = lightTexel(vLight * 4);
    bool inside = drawn && distance(positionRadius.xyz, pos) < positionRadius.w;
#ifndef COVERAGE
    // Adding zero instead of discarding: a shader that may discard makes llvmpipe (and many
    // GPUs) run it before the depth test, and in the stencil cull mode a discarded fragment
    // would skip the stencil reset and leave its mark for the next light.
    if (!inside) {
        fragColor = fragSpecular = vec4(0.0);
        return;
    }
#endif
    Light l = fetchLight(vLight);
#ifdef COVERAGE
    vec3 lit = inside ? shadeLight(l, pos, gbufferNormal(px), vec3(1.0), 1.0) : vec3(0.0);
    fragColor = vec4(1.0, any(greaterThan(lit, vec3(0.0))) ? 1.0 : 0.0, 0.0, 0.0);
#elif defined(PREPASS_LIGHTS)
    LightSum sum = noLight();
    accumulateLight(sum, l, surface, 1.0);
    fragColor = vec4(sum.diffuse, 0.0);
    fragSpecular = vec4(sum.specular, 0.0);
#else
    vec4 as = gbufferAlbedoSpec(px);
    LightSum sum = noLight();
    accumulateLight(sum, l, surfacePoint(pos, gbufferNormal(px)), as.a);
    // Blended additively: the surface terms came with the full-screen pass before the volumes.
    fragColor = vec4(accumulationTarget0(sum, vec3(0.0), as.rgb).rgb, 0.0);
    fragSpecular = vec4(sum.specular, 0.0);
#endif
}
