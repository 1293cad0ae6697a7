// prepass (deferred lighting, docs/deferred_lighting.md): every light at each pixel of the thin
// G-buffer, summed into two targets: diffuse light (N.L * attenuation * colour) and specular light
// ((N.H)^exponent * attenuation * colour). The thin G-buffer holds no material, so the specular
// intensity is 1 here; prepass_shade.frag multiplies the sums by albedo and intensity. Built with
// GBL_SHININESS_PER_PIXEL: the exponent is the one the pixel stored (lighting.glsl).
#version 330 core
#include "bindings.glsl"
#include "lighting.glsl"
#include "light_fetch.glsl"
#include "light_accumulation.glsl"

uniform sampler2D uPrepassNormal;  // xyz unit world normal, w specular exponent
uniform sampler2D uDepth;          // the thin pass's depth (window space, 1 = background)
uniform mat4 uInverseViewProj;
uniform int uLightCount;

layout(location = 0) out vec4 fragDiffuse;
layout(location = 1) out vec4 fragSpecular;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    float d = texelFetch(uDepth, px, 0).r;
    fragDiffuse = vec4(0.0);
    fragSpecular = vec4(0.0);
    if (d >= 1.0) return;  // background: the thin pass clears depth to 1 and draws with GL_LESS
    // The world position rebuilt from depth, as gbuffer_read.glsl does for the layouts without one.
    vec2 ndc = (vec2(px) + 0.5) / vec2(textureSize(uDepth, 0)) * 2.0 - 1.0;
    vec4 world = uInverseViewProj * vec4(ndc, d * 2.0 - 1.0, 1.0);
    vec4 stored = texelFetch(uPrepassNormal, px, 0);
    gShininess = stored.w;
    SurfacePoint s = surfacePoint(world.xyz / world.w, normalize(stored.xyz));
    LightSum sum = noLight();
    accumulateGlobalLights(sum, s, 1.0);
    // Every light in index order, LIGHTS_PER_ITERATION at a time, as the quad pass does.
#define ADD(j) accumulateListedLight(sum, j, true, s, 1.0)
    FOR_EVERY_LIGHT(uLightCount, ADD)
#undef ADD
    fragDiffuse = vec4(sum.diffuse, 1.0);
    fragSpecular = vec4(sum.specular, 1.0);
}
