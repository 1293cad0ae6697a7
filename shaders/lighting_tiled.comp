// Tiled lighting (OpenGL 4.3): one work group per 16x16-pixel tile keeps the lights whose sphere
// touches the tile's frustum between the depth bounds of its pixels (renderer/tile_math.h does the
// same on the CPU), then shades its pixels with only those. The bounds come from tile_depth.comp
// and the lights tested are the tile's candidates from the binning pass (tile_bin.comp); a tile
// with more candidates than the bins hold tests every light instead.
#version 430 core
#include "bindings.glsl"
#include "shader_checks.glsl"
#include "lighting.glsl"
#include "light_fetch.glsl"
#include "gbuffer_read.glsl"
#include "tile_bin_read.glsl"
#include "surface_terms.glsl"
#include "light_accumulation.glsl"

layout(local_size_x = GBL_TILE_SIZE, local_size_y = GBL_TILE_SIZE) in;  // GBL_TILE_SIZE: kTileSize, core/tile_math.h
const int TILE_INVOCATIONS = GBL_TILE_SIZE * GBL_TILE_SIZE;

layout(rgba16f, binding = BIND_IMAGE_LIGHTING) uniform writeonly image2D uLightingImage;
layout(rg32f, binding = BIND_IMAGE_COVERAGE) uniform writeonly image2D uCoverageImage;
layout(rgba16f, binding = BIND_IMAGE_SPECULAR_LIGHT) uniform writeonly image2D uSpecularImage;  // split only

uniform int uLightCount;
uniform vec3 uAmbient;
uniform mat4 uView;
uniform ivec2 uScreenSize;
uniform bool uShade;          // write the lit image
uniform bool uWriteCoverage;  // write x = lights in the tile, y = lights that lit the pixel

// A bit per light of one chunk of 16,384 lights: shading walks the set bits in index order, so
// each pixel adds its lights in the same order as the full-screen pass. More lights (up to
// kMaxLights = 262,144) run as consecutive chunks, each culled and shaded in turn: no light is
// ever dropped, so the list has no cap, and the order stays the full-screen pass's.
#define MAX_LIGHT_WORDS 512
#define CHUNK_LIGHTS (MAX_LIGHT_WORDS * 32)
shared uint sLightMask[MAX_LIGHT_WORDS];
shared uint sWords[MAX_LIGHT_WORDS];  // indices of the non-empty words of sLightMask, ascending
shared uint sWordCount;
#include "tile_depth_buffer.glsl"

#include "tile_frustum.glsl"

// Whether light `index` may reach a surface of the tile: its sphere reaches the tile's depth range
// and lies on the inner side of (or crosses) the four side planes. The one culling test of this
// pass (the binned and the every-light paths both call it).
bool lightTouchesTile(int index, float minDepth, float maxDepth, vec3 left, vec3 right, vec3 bottom, vec3 top,
                      vec3 tileCentre, float tileRadius) {
    vec4 positionRadius = lightTexel(index * 4);
    float r = positionRadius.w;
    vec3 c = (uView * vec4(positionRadius.xyz, 1.0)).xyz;
    float depth = -c.z;
    bool touches = r > 0.0 && depth + r >= minDepth && depth - r <= maxDepth && dot(left, c) >= -r &&
                   dot(right, c) >= -r && dot(bottom, c) >= -r && dot(top, c) >= -r;
    // Spots: then the cone against a sphere around the tile's frustum between its depth bounds.
    return touches && coneMayTouchSphere(index, mat3(uView), c, tileCentre, tileRadius);
}

// Adds light `index` at the pixel if `listed` (accumulateListedLight says how lights that miss
// it are skipped).
void addLight(int index, bool listed, SurfacePoint s, vec4 as, inout LightSum sum, inout float lit) {
    // "Lit" as in light_volume.frag: the light reaches a surface that faces it.
    lit += accumulateListedLight(sum, index, listed, s, as.a) ? 1.0 : 0.0;
}


void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    uint local = gl_LocalInvocationIndex;
    int tile = int(gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x);
    bool onScreen = px.x < uScreenSize.x && px.y < uScreenSize.y;
    vec3 pos = vec3(0.0);
    bool geometry = onScreen && gbufferPosition(px, pos);

    // The tile's depth bounds and frustum side planes, once for every chunk.
    vec2 depthRange = tileDepth[CHECKED(CHECK_SITE_TILE_DEPTH, tile, tileDepth.length())];
    float minDepth = depthRange.x, maxDepth = depthRange.y;
    bool anyGeometry = maxDepth != 0.0;  // the same in every invocation: uniform flow below
    ivec2 lo = ivec2(gl_WorkGroupID.xy) * GBL_TILE_SIZE, hi = min(lo + GBL_TILE_SIZE, uScreenSize);
    vec2 ndcLo = vec2(lo) / vec2(uScreenSize) * 2.0 - 1.0, ndcHi = vec2(hi) / vec2(uScreenSize) * 2.0 - 1.0;
    vec3 bl = unprojectFar(ndcLo), br = unprojectFar(vec2(ndcHi.x, ndcLo.y));
    vec3 tl = unprojectFar(vec2(ndcLo.x, ndcHi.y)), tr = unprojectFar(ndcHi);
    vec3 centre = (bl + br + tl + tr) * 0.25;
    // Four named planes rather than an array: llvmpipe spills indexed arrays to memory.
    vec3 left = sidePlane(bl, tl, centre).xyz, right = sidePlane(br, tr, centre).xyz;
    vec3 bottom = sidePlane(bl, br, centre).xyz, top = sidePlane(tl, tr, centre).xyz;
    // A sphere around the tile's frustum between its depth bounds, for the spot lights' cone test:
    // the far corners scaled to each bound (view depth d: corner * d / the far plane's depth).
    float farDepth = -bl.z;
    vec3 tileCentre = (bl + br + tl + tr) * 0.25 * ((minDepth + maxDepth) * 0.5 / farDepth);
    float tileRadius = 0.0;
    for (int k = 0; k < 8; ++k) {
        vec3 corner = (k & 3) == 0 ? bl : (k & 3) == 1 ? br : (k & 3) == 2 ? tl : tr;
        tileRadius = max(tileRadius, distance(tileCentre, corner * ((k < 4 ? minDepth : maxDepth) / farDepth)));
    }

    vec3 n = vec3(0.0);
    vec4 as = vec4(0.0), ea = vec4(0.0);
    if (geometry) {
        n = gbufferNormal(px);
        as = gbufferAlbedoSpec(px);
        ea = gbufferEmissiveAo(px);
    }
    vec3 surface = surfaceTerms(uAmbient, as.rgb, ea.a, ea.rgb);
    SurfacePoint s = surfacePoint(pos, n);
    LightSum sum = noLight();
    if (geometry) accumulateGlobalLights(sum, s, as.a);  // directional: in no tile list
    float lit = 0.0;
    uint tileCount = 0u;
    // Every work group empties its list here, also a tile with nothing drawn (which then keeps
    // nothing): sortKeptLights() below reads the list's count in every tile.
    int binned = tileBinCandidates(tile);
    if (!anyGeometry) binned = 0;
    if (binned >= 0) {
        // --- light list: the tile's candidates, each invocation testing every 256th ---
        for (int k = int(local); k < binned; k += TILE_INVOCATIONS) {
            int index = binnedLight(tile, k);
            if (lightTouchesTile(index, minDepth, maxDepth, left, right, bottom, top, tileCentre, tileRadius)) keepLight(index);
        }
        int kept = sortKeptLights();
        tileCount = uint(kept);
        // --- shading: the tile's lights in ascending index order ---
        // Four list entries a read (tile_bin_read.glsl says why); the entries up to the next
        // multiple of four past `kept` are padding, not listed.
        for (int k = 0; geometry && k < kept; k += 4) {
            uvec4 four = sSorted4[CHECKED(CHECK_SITE_SORTED, k >> 2, BIN_MAX / 4)];
            addLight(int(four.x), true, s, as, sum, lit);
            addLight(int(four.y), k + 1 < kept, s, as, sum, lit);
            addLight(int(four.z), k + 2 < kept, s, as, sum, lit);
            addLight(int(four.w), k + 3 < kept, s, as, sum, lit);
        }
    }
    // Over the bins' cap: every light, in chunks (the same test, the same order).
    for (int base = 0; binned < 0 && base < uLightCount; base += CHUNK_LIGHTS) {
        int chunk = min(uLightCount - base, CHUNK_LIGHTS);
        int words = (chunk + 31) / 32;
        for (int w = int(local); w < words; w += TILE_INVOCATIONS) sLightMask[CHECKED(CHECK_SITE_LIGHT_MASK, w, MAX_LIGHT_WORDS)] = 0u;
        memoryBarrierShared();
        barrier();

        // --- light list: every invocation tests every 256th light of the chunk ---
        for (int i = int(local); i < chunk; i += TILE_INVOCATIONS)
            if (lightTouchesTile(base + i, minDepth, maxDepth, left, right, bottom, top, tileCentre, tileRadius))
                atomicOr(sLightMask[CHECKED(CHECK_SITE_LIGHT_MASK, i >> 5, MAX_LIGHT_WORDS)], 1u << uint(i & 31));
        memoryBarrierShared();
        barrier();
        // The non-empty words, in order, so pixels skip the empty ones (most, for small lights).
        if (local == 0u) {
            uint count = 0u;
            for (int w = 0; w < words; ++w)
                if (sLightMask[w] != 0u) sWords[CHECKED(CHECK_SITE_LIGHT_WORDS, count++, MAX_LIGHT_WORDS)] = uint(w);
            sWordCount = count;
        }
        memoryBarrierShared();
        barrier();

        // --- shading: the chunk's lights of this tile in index order ---
        if (geometry) {
            for (uint k = 0u; k < sWordCount; ++k) {
                int w = int(sWords[k]);
                uint bits = sLightMask[w];
                while (bits != 0u) {
                    int b = findLSB(bits);
                    bits &= bits - 1u;
                    addLight(base + w * 32 + b, true, s, as, sum, lit);
                }
            }
        }
        if (uWriteCoverage)
            for (uint k = 0u; k < sWordCount; ++k) tileCount += uint(bitCount(sLightMask[sWords[k]]));
        // Every invocation is done with this chunk's list before the next one overwrites it.
        barrier();
    }
    if (!onScreen) return;
    px = CHECKED_PIXEL(px, imageSize(uLightingImage));
    if (uShade) imageStore(uLightingImage, px, geometry ? accumulationTarget0(sum, surface, as.rgb) : vec4(0.0));
    if (uShade && uSplitAccumulation) imageStore(uSpecularImage, px, geometry ? vec4(sum.specular, 1.0) : vec4(0.0));
    if (uWriteCoverage) imageStore(uCoverageImage, px, vec4(float(tileCount), lit, 0.0, 0.0));
}
