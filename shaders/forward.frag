// Forward shading: every light evaluated per fragment while drawing each object (no G-buffer).
// Used by the `forward` lighting mode and for alpha-blended materials after deferred lighting.
// Built with FORWARD_TILE_LISTS (the forward+ mode): each fragment shades with its 16x16 tile's
// candidate lights from the binning pass (tile_bin.comp) instead, after a depth pre-pass.
// Built with FORWARD_TONEMAP: the blended surfaces again, over the light cubes on the display image
// (tonemapped as the cubes are; passes/light_cubes.h).
#version 330 core
#ifdef FORWARD_TILE_LISTS
// Storage buffers, binding points and early depth tests: OpenGL 4.3's, where the mode can run.
#extension GL_ARB_shader_storage_buffer_object : require
#extension GL_ARB_shading_language_420pack : require
#extension GL_ARB_shader_image_load_store : require
#endif
#include "bindings.glsl"
#include "material.glsl"
#include "lighting.glsl"
#include "light_fetch.glsl"
#include "surface_terms.glsl"
#ifdef FORWARD_TONEMAP
#include "view_constants.glsl"
#include "tonemap.glsl"
#endif

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUV;
in vec4 vTangent;

uniform vec3 uAmbient;
uniform int uLightCount;

out vec4 fragColor;

#ifdef FORWARD_TILE_LISTS
// The depth pre-pass kept only the nearest surface (alpha mask applied), and this pass writes no
// depth: testing before the shader runs shades each pixel once.
layout(early_fragment_tests) in;
layout(std430, binding = BIND_SSBO_TILE_BIN_COUNTS) readonly buffer TileBinCounts { uint tileBinCount[]; };
layout(std430, binding = BIND_SSBO_TILE_BIN_LIGHTS) readonly buffer TileBinLights { uint tileBinLight[]; };
uniform int uBinCap;   // entries per tile (TileBins::cap)
uniform int uTilesX;   // tiles per row (core/tile_math.h, tileGrid)
#endif

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
#ifdef FORWARD_TILE_LISTS
    // The tile's candidates, in the order they were binned; a tile over the bins' cap has an
    // incomplete list and shades with every light, as lighting_tiled.comp does.
    ivec2 t = ivec2(gl_FragCoord.xy) / GBL_TILE_SIZE;
    int tile = t.y * uTilesX + t.x;
    int listed = int(tileBinCount[tile]);
    if (listed <= uBinCap) {
        for (int k = 0; k < listed; ++k) ADD(int(tileBinLight[tile * uBinCap + k]));
    } else {
        FOR_EVERY_LIGHT(uLightCount, ADD)
    }
#else
    FOR_EVERY_LIGHT(uLightCount, ADD)
#endif
#undef ADD
#ifdef FORWARD_TONEMAP
    fragColor = vec4(tonemap(color), base.a);
#else
    fragColor = vec4(color, base.a);
#endif
}
