// Clustered lighting, step 1 (OpenGL 4.3): one work group per 16x16-pixel tile first culls the
// tile's candidate lights from the binning pass (tile_bin.comp) against the tile's frustum (as
// lighting_tiled.comp does), then one invocation per exponential depth slice lists, in index
// order, the tile's lights whose sphere reaches that slice's view-space box
// (renderer/core/cluster_math.h does the same on the CPU). A tile with more candidates than the
// bins hold tests every light instead. Either way the tile's own sorted list is left in its bin
// (when it fits) for cluster_shade.comp's clusters over their cap.
#version 430 core
#include "bindings.glsl"
#include "shader_checks.glsl"
#include "lighting.glsl"
#include "light_fetch.glsl"
#include "tile_frustum.glsl"
#define TILE_BIN_ACCESS
#include "tile_bin_read.glsl"

layout(local_size_x = 256) in;

layout(std430, binding = BIND_SSBO_CLUSTER_COUNTS) writeonly buffer ClusterCounts { uint clusterCount[]; };
layout(std430, binding = BIND_SSBO_CLUSTER_LIGHTS) writeonly buffer ClusterLights { uint clusterLight[]; };

uniform int uLightCount;
uniform mat4 uView;
uniform ivec2 uScreenSize;
uniform ivec3 uGrid;  // tiles x, tiles y, slices (at most 256: one invocation each)
uniform int uMaxLights;  // list entries per cluster (ClusterLists::cap, at most kClusterMaxLights)
uniform float uNear;
uniform float uFar;

// The tile's lights, a bit each, in chunks of 16,384 as in lighting_tiled.comp: no cap, index order.
#define MAX_LIGHT_WORDS 512
#define CHUNK_LIGHTS (MAX_LIGHT_WORDS * 32)
shared uint sLightMask[MAX_LIGHT_WORDS];
shared uint sWords[MAX_LIGHT_WORDS];
shared uint sWordCount;
shared uint sTileKept;  // over the bins' cap: the tile's lights so far (every chunk's)

float sliceNear(int slice) { return uNear * pow(uFar / uNear, float(slice) / float(uGrid.z)); }

// Whether light `index` may reach the tile between the near and far planes: its sphere lies on the
// inner side of (or crosses) the four side planes (the tile test of lighting_tiled.comp).
bool lightTouchesTile(int index, vec3 left, vec3 right, vec3 bottom, vec3 top) {
    vec4 pr = lightTexel(index * 4);
    float r = pr.w;
    vec3 c = (uView * vec4(pr.xyz, 1.0)).xyz;
    float depth = -c.z;
    return r > 0.0 && depth + r >= uNear && depth - r <= uFar && dot(left, c) >= -r && dot(right, c) >= -r &&
           dot(bottom, c) >= -r && dot(top, c) >= -r;
}

// Whether light `index` (already in the tile's list) reaches the cluster's view-space box.
bool lightTouchesCluster(int index, vec3 boxLo, vec3 boxHi) {
    vec4 pr = lightTexel(index * 4);
    vec3 c = (uView * vec4(pr.xyz, 1.0)).xyz;
    // A hair larger than the radius: a pixel on a slice boundary, put in the neighbouring slice by
    // rounding, still finds every light that reaches it.
    float r = pr.w * 1.0001 + 1e-4;
    vec3 d = c - clamp(c, boxLo, boxHi);
    if (dot(d, d) > r * r) return false;
    // Spots: then the cone against a sphere around the cluster's box.
    return coneMayTouchSphere(index, mat3(uView), c, (boxLo + boxHi) * 0.5, length(boxHi - boxLo) * 0.5);
}

void main() {
    int local = int(gl_LocalInvocationIndex);
    ivec2 tile = ivec2(gl_WorkGroupID.xy);
    int slice = local;
    bool owner = slice < uGrid.z;  // this invocation builds cluster (tile, slice)

    ivec2 lo = tile * GBL_TILE_SIZE, hi = min(lo + GBL_TILE_SIZE, uScreenSize);
    vec2 ndcLo = vec2(lo) / vec2(uScreenSize) * 2.0 - 1.0, ndcHi = vec2(hi) / vec2(uScreenSize) * 2.0 - 1.0;
    vec3 bl = unprojectFar(ndcLo), br = unprojectFar(vec2(ndcHi.x, ndcLo.y));
    vec3 tl = unprojectFar(vec2(ndcLo.x, ndcHi.y)), tr = unprojectFar(ndcHi);
    vec3 centre = (bl + br + tl + tr) * 0.25;
    vec3 left = sidePlane(bl, tl, centre).xyz, right = sidePlane(br, tr, centre).xyz;
    vec3 bottom = sidePlane(bl, br, centre).xyz, top = sidePlane(tl, tr, centre).xyz;

    // The box around the tile's four corner rays between the slice's depths.
    vec3 boxLo = vec3(3.0e38), boxHi = vec3(-3.0e38);
    if (owner) {
        float d0 = sliceNear(slice), d1 = sliceNear(slice + 1);
        for (int corner = 0; corner < 4; ++corner) {
            vec2 ndc = vec2((corner & 1) != 0 ? ndcHi.x : ndcLo.x, (corner & 2) != 0 ? ndcHi.y : ndcLo.y);
            vec3 ray = unprojectFar(ndc);
            ray /= -ray.z;  // the point at view depth 1
            boxLo = min(boxLo, min(ray * d0, ray * d1));
            boxHi = max(boxHi, max(ray * d0, ray * d1));
        }
    }
    int cluster = (slice * uGrid.y + tile.y) * uGrid.x + tile.x;
    uint base = uint(cluster) * uint(uMaxLights);
    uint count = 0u;

    int tileIndex = tile.y * uGrid.x + tile.x;
    int binned = tileBinCandidates(tileIndex);
    if (binned >= 0) {
        // --- the tile's lights: its candidates, each invocation testing every 256th ---
        for (int k = local; k < binned; k += 256) {
            int index = binnedLight(tileIndex, k);
            if (lightTouchesTile(index, left, right, bottom, top)) keepLight(index);
        }
        int kept = sortKeptLights();
        // The tile's sorted list replaces its bin (no invocation reads the bin any more): a cluster
        // over its own cap shades from it in cluster_shade.comp instead of from every light.
        for (int k = local; k < kept; k += 256) tileBinLight[CHECKED(CHECK_SITE_TILE_BIN_LIGHT, uint(tileIndex) * uint(uBinCap) + uint(k), tileBinLight.length())] = sortedLight(k);
        if (local == 0) tileBinCount[tileIndex] = uint(kept);
        // --- each slice keeps the tile's lights that reach its box, in index order ---
        for (int k = 0; owner && k < kept; ++k) {
            int index = int(sortedLight(k));
            if (lightTouchesCluster(index, boxLo, boxHi)) {
                if (count < uint(uMaxLights)) clusterLight[CHECKED(CHECK_SITE_CLUSTER_LIGHT, base + count, clusterLight.length())] = uint(index);
                ++count;  // the true count, also past the cap (cluster_shade.comp then loops over all)
            }
        }
    }
    // Over the bins' cap: every light, in chunks (the same tests, the same order). The tile's lights
    // found on the way are written to its bin, in index order, while they fit: a cluster over its
    // own cap then shades from that list rather than from every light.
    if (local == 0) sTileKept = 0u;
    for (int start = 0; binned < 0 && start < uLightCount; start += CHUNK_LIGHTS) {
        int chunk = min(uLightCount - start, CHUNK_LIGHTS);
        int words = (chunk + 31) / 32;
        for (int w = local; w < words; w += 256) sLightMask[w] = 0u;
        memoryBarrierShared();
        barrier();
        // --- the tile's lights: every invocation tests every 256th light of the chunk ---
        for (int i = local; i < chunk; i += 256)
            if (lightTouchesTile(start + i, left, right, bottom, top)) atomicOr(sLightMask[i >> 5], 1u << uint(i & 31));
        memoryBarrierShared();
        barrier();
        if (local == 0) {
            uint n = 0u;
            for (int w = 0; w < words; ++w)
                if (sLightMask[w] != 0u) sWords[n++] = uint(w);
            sWordCount = n;
            for (uint k = 0u; k < n; ++k) {
                uint bits = sLightMask[sWords[k]];
                while (bits != 0u) {
                    int b = findLSB(bits);
                    bits &= bits - 1u;
                    if (sTileKept < uint(uBinCap))
                        tileBinLight[CHECKED(CHECK_SITE_TILE_BIN_LIGHT, uint(tileIndex) * uint(uBinCap) + sTileKept, tileBinLight.length())] = uint(start + int(sWords[k]) * 32 + b);
                    ++sTileKept;
                }
            }
        }
        memoryBarrierShared();
        barrier();
        // --- each slice keeps the tile's lights that reach its box, in index order ---
        if (owner) {
            for (uint k = 0u; k < sWordCount; ++k) {
                int w = int(sWords[k]);
                uint bits = sLightMask[w];
                while (bits != 0u) {
                    int b = findLSB(bits);
                    bits &= bits - 1u;
                    int index = start + w * 32 + b;
                    if (lightTouchesCluster(index, boxLo, boxHi)) {
                        if (count < uint(uMaxLights)) clusterLight[CHECKED(CHECK_SITE_CLUSTER_LIGHT, base + count, clusterLight.length())] = uint(index);
                        ++count;  // the true count, also past the cap (cluster_shade.comp then loops over all)
                    }
                }
            }
        }
        // Every slice is done with this chunk's list before the next one overwrites it.
        barrier();
    }
    if (owner) clusterCount[CHECKED(CHECK_SITE_CLUSTER_COUNT, cluster, clusterCount.length())] = count;
    // The tile's true count: its list in the bin is complete when the count is within the cap.
    if (binned < 0 && local == 0) tileBinCount[tileIndex] = sTileKept;
}
