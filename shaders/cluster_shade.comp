// Clustered lighting, step 2 (OpenGL 4.3): each pixel finds its cluster (tile and exponential
// depth slice) and shades with that cluster's light list, in index order like the full-screen pass.
#version 430 core
#include "bindings.glsl"
#include "shader_checks.glsl"
#include "lighting.glsl"
#include "light_fetch.glsl"
#include "gbuffer_read.glsl"
#include "surface_terms.glsl"
#include "light_accumulation.glsl"

layout(local_size_x = GBL_TILE_SIZE, local_size_y = GBL_TILE_SIZE) in;  // GBL_TILE_SIZE: kTileSize, core/tile_math.h

layout(rgba16f, binding = BIND_IMAGE_LIGHTING) uniform writeonly image2D uLightingImage;
layout(rg32f, binding = BIND_IMAGE_COVERAGE) uniform writeonly image2D uCoverageImage;
layout(rgba16f, binding = BIND_IMAGE_SPECULAR_LIGHT) uniform writeonly image2D uSpecularImage;  // split only
layout(std430, binding = BIND_SSBO_CLUSTER_COUNTS) readonly buffer ClusterCounts { uint clusterCount[]; };
// The lists themselves, read as a buffer texture: llvmpipe fetches a texel for all of a vector's
// pixels at once, where it reads a storage buffer one pixel at a time.
uniform usamplerBuffer uClusterList;
// Each tile's sorted light list, as cluster_build.comp left it (a count past uBinCap: none).
layout(std430, binding = BIND_SSBO_TILE_BIN_COUNTS) readonly buffer TileBinCounts { uint tileBinCount[]; };
layout(std430, binding = BIND_SSBO_TILE_BIN_LIGHTS) readonly buffer TileBinLights { uint tileBinLight[]; };
uniform int uBinCap;

uniform int uLightCount;
uniform vec3 uAmbient;
uniform mat4 uView;
uniform ivec2 uScreenSize;
uniform ivec3 uGrid;
uniform int uMaxLights;
uniform float uNear;
uniform float uFar;
uniform bool uShade;          // write the lit image
uniform bool uWriteCoverage;  // write x = lights in the cluster's list, y = lights that lit the pixel

void addLight(int i, SurfacePoint s, vec4 as, inout LightSum color, inout float lit) {
    // "Lit" as in light_volume.frag: the light reaches a surface that faces it.
    lit += accumulateListedLight(color, i, true, s, as.a) ? 1.0 : 0.0;
}

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (px.x >= uScreenSize.x || px.y >= uScreenSize.y) return;
    vec3 pos;
    if (!gbufferPosition(px, pos)) {
        if (uShade) imageStore(uLightingImage, px, vec4(0.0));
        if (uShade && uSplitAccumulation) imageStore(uSpecularImage, px, vec4(0.0));
        if (uWriteCoverage) imageStore(uCoverageImage, px, vec4(0.0));
        return;
    }
    vec3 n = gbufferNormal(px);
    vec4 as = gbufferAlbedoSpec(px);
    vec4 ea = gbufferEmissiveAo(px);
    vec3 surface = surfaceTerms(uAmbient, as.rgb, ea.a, ea.rgb);
    SurfacePoint s = surfacePoint(pos, n);
    LightSum color = noLight();  // the pixel's light sums (light_accumulation.glsl)
    accumulateGlobalLights(color, s, as.a);  // directional: in no cluster list
    float lit = 0.0;
    float depth = -(uView * vec4(pos, 1.0)).z;
    int slice = clamp(int(floor(log(depth / uNear) / log(uFar / uNear) * float(uGrid.z))), 0, uGrid.z - 1);
    int cluster = (slice * uGrid.y + px.y / GBL_TILE_SIZE) * uGrid.x + px.x / GBL_TILE_SIZE;
    uint count = clusterCount[CHECKED(CHECK_SITE_CLUSTER_COUNT, cluster, clusterCount.length())];
    if (count <= uint(uMaxLights)) {
        uint base = uint(cluster) * uint(uMaxLights);
        for (uint k = 0u; k < count; ++k) addLight(int(texelFetch(uClusterList, int(base + k)).r), s, as, color, lit);
    } else {
        // Over the cap: the cluster's list is incomplete, so the tile's whole list (a superset, in
        // index order) is tried, or every light where the tile's bin overflowed too (exact, slower).
        int tile = (px.y / GBL_TILE_SIZE) * uGrid.x + px.x / GBL_TILE_SIZE;
        uint tileCount = tileBinCount[CHECKED(CHECK_SITE_TILE_BIN_COUNT, tile, tileBinCount.length())];
        if (tileCount <= uint(uBinCap)) {
            uint base = uint(tile) * uint(uBinCap);
            for (uint k = 0u; k < tileCount; ++k) addLight(int(tileBinLight[CHECKED(CHECK_SITE_TILE_BIN_LIGHT, base + k, tileBinLight.length())]), s, as, color, lit);
            count = tileCount;  // what was evaluated
        } else {
            // LIGHTS_PER_ITERATION lights an iteration (light_fetch.glsl says why).
#define ADD(j) addLight(j, s, as, color, lit)
            FOR_EVERY_LIGHT(uLightCount, ADD)
#undef ADD
        }
    }
    if (uShade) imageStore(uLightingImage, px, accumulationTarget0(color, surface, as.rgb));
    if (uShade && uSplitAccumulation) imageStore(uSpecularImage, px, vec4(color.specular, 1.0));
    if (uWriteCoverage) imageStore(uCoverageImage, px, vec4(float(count), lit, 0.0, 0.0));
}
