// Reading one tile's candidate lights from the binning pass (tile_bin.comp), for compute shaders
// with 256 invocations per work group. The caller tests the tile's candidates (each invocation
// every 256th, straight from the bin), keeps the ones that pass with keepLight(), and
// sortKeptLights() then lists them in ascending index order, so each pixel adds its lights in
// the full-screen pass's order.
#ifndef GBL_TILE_BIN_READ_GLSL
#define GBL_TILE_BIN_READ_GLSL
// cluster_build.comp defines TILE_BIN_ACCESS empty: it writes each tile's sorted list back.
#ifndef TILE_BIN_ACCESS
#define TILE_BIN_ACCESS readonly
#endif
layout(std430, binding = BIND_SSBO_TILE_BIN_COUNTS) TILE_BIN_ACCESS buffer TileBinCounts { uint tileBinCount[]; };
layout(std430, binding = BIND_SSBO_TILE_BIN_LIGHTS) TILE_BIN_ACCESS buffer TileBinLights { uint tileBinLight[]; };
uniform int uBinCap;  // entries per tile (TileBins::cap, at most kTileBinMaxLights)

#define BIN_MAX 1024  // kTileBinMaxLights
shared uint sKept[BIN_MAX];    // the candidates kept, in the order the invocations kept them
// The same, ascending: the tile's light list, four to a vector. Shading reads four at once:
// llvmpipe loads shared memory one invocation at a time, so one uvec4 read costs about what one
// uint read does (lighting_tiled.comp's shading loop was 4-6 % faster for it at 512 lights).
shared uvec4 sSorted4[BIN_MAX / 4];
shared uint sKeptCount;

// The tile's candidate count, or -1 when the binning pass found more than the cap (the bin is
// incomplete: the caller tests every light instead). Every invocation of the work group calls it
// (it holds a barrier) and gets the same answer; candidate k is then binnedLight(tile, k). It also
// empties the kept list, so it comes before any keepLight() or sortKeptLights() of the work group,
// whatever the tile holds: shared memory starts undefined, and a list never emptied has a count
// of whatever was there.
int tileBinCandidates(int tile) {
    if (gl_LocalInvocationIndex == 0u) sKeptCount = 0u;
    memoryBarrierShared();
    barrier();
    uint n = tileBinCount[CHECKED(CHECK_SITE_TILE_BIN_COUNT, tile, tileBinCount.length())];
    return n > uint(uBinCap) ? -1 : int(n);
}

int binnedLight(int tile, int k) {
    return int(tileBinLight[CHECKED(CHECK_SITE_TILE_BIN_LIGHT, uint(tile) * uint(uBinCap) + uint(k), tileBinLight.length())]);
}

// Keeps a candidate; a tile never keeps more than its bin's cap (at most BIN_MAX) candidates, and
// an index past the list is dropped rather than written outside it.
void keepLight(int index) {
    uint slot = atomicAdd(sKeptCount, 1u);
    if (slot < uint(BIN_MAX)) sKept[CHECKED(CHECK_SITE_KEPT, slot, BIN_MAX)] = uint(index);
}

// After every invocation has kept its lights: sorts them into sSorted and returns how many.
// Rank sort: a light's place is the number of smaller indices (each light is binned once per tile).
uint sortedLight(int k) { return sSorted4[CHECKED(CHECK_SITE_SORTED, k >> 2, BIN_MAX / 4)][k & 3]; }

int sortKeptLights() {
    memoryBarrierShared();
    barrier();
    uint n = min(sKeptCount, uint(BIN_MAX));
    for (uint k = gl_LocalInvocationIndex; k < n; k += 256u) {
        uint index = sKept[k], rank = 0u;
        for (uint j = 0u; j < n; ++j) rank += sKept[j] < index ? 1u : 0u;
        sSorted4[CHECKED(CHECK_SITE_SORTED, rank >> 2u, BIN_MAX / 4)][rank & 3u] = index;
    }
    // Padding up to the next multiple of four, for readers that take four entries at a time: light
    // 0, which exists whenever the list is not empty (they fetch it and add nothing).
    uint pad = n + gl_LocalInvocationIndex;
    if (gl_LocalInvocationIndex < 3u && pad < uint(BIN_MAX)) sSorted4[pad >> 2u][pad & 3u] = 0u;
    memoryBarrierShared();
    barrier();
    return int(n);
}
#endif
