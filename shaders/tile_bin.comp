// Light binning (OpenGL 4.3): one invocation per light appends the light's index to the candidate
// list of every 16x16 tile its bounding sphere can cover on screen (renderer/core/tile_math.h,
// sphereTileRange, is the CPU twin). lighting_tiled.comp and cluster_build.comp then test only a
// tile's candidates: the work grows with the tiles each light covers, not lights x tiles.
#version 430 core
#include "bindings.glsl"
#include "shader_checks.glsl"
#include "lighting.glsl"
#include "light_fetch.glsl"

layout(local_size_x = 64) in;

// Zeroed before the dispatch; each count is the tile's true candidate count, also past the cap.
layout(std430, binding = BIND_SSBO_TILE_BIN_COUNTS) buffer TileBinCounts { uint tileBinCount[]; };
layout(std430, binding = BIND_SSBO_TILE_BIN_LIGHTS) writeonly buffer TileBinLights { uint tileBinLight[]; };
#include "tile_depth_buffer.glsl"

uniform int uLightCount;
uniform mat4 uView;
uniform mat4 uProjection;
uniform ivec2 uScreenSize;
uniform ivec2 uTiles;
uniform int uBinCap;  // entries per tile (TileBins::cap)
uniform float uNear;
uniform float uFar;
// forward+'s lists for the blended surfaces: a pane may lie anywhere in front of the tile's farthest
// opaque pixel (it is depth-tested against that depth), and over a tile with none at all.
uniform bool uFromNear;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= uLightCount) return;
    vec4 pr = lightTexel(i * 4);
    float r = pr.w;
    vec3 c = (uView * vec4(pr.xyz, 1.0)).xyz;
    float depth = -c.z;
    if (!(r > 0.0) || depth + r < uNear || depth - r > uFar) return;
    ivec2 t0 = ivec2(0), t1 = uTiles - 1;
    if (depth - r > uNear) {
        // Wholly past the near plane: the projection of the sphere's view-space box, widened by a
        // pixel for rounding. A sphere crossing the near plane keeps every tile.
        vec2 lo = vec2(3.0e38), hi = vec2(-3.0e38);
        for (int corner = 0; corner < 8; ++corner) {
            vec3 s = vec3((corner & 1) != 0 ? 1.0 : -1.0, (corner & 2) != 0 ? 1.0 : -1.0, (corner & 4) != 0 ? 1.0 : -1.0);
            vec4 clip = uProjection * vec4(c + r * s, 1.0);
            vec2 ndc = clip.xy / clip.w;
            lo = min(lo, ndc);
            hi = max(hi, ndc);
        }
        vec2 size = vec2(uScreenSize), margin = vec2(float(GBL_TILE_SIZE));
        vec2 pxLo = clamp((lo * 0.5 + 0.5) * size - 1.0, -margin, size + margin);
        vec2 pxHi = clamp((hi * 0.5 + 0.5) * size + 1.0, -margin, size + margin);
        t0 = max(ivec2(floor(pxLo / float(GBL_TILE_SIZE))), ivec2(0));
        t1 = min(ivec2(floor(pxHi / float(GBL_TILE_SIZE))), uTiles - 1);
    }
    for (int ty = t0.y; ty <= t1.y; ++ty)
        for (int tx = t0.x; tx <= t1.x; ++tx) {
            uint tile = uint(ty * uTiles.x + tx);
            // A light wholly in front of or behind every drawn pixel of the tile reaches none of
            // them (a pixel farther than r in depth is farther than r away): not a candidate. The
            // list passes test the same range again; the hair of slack keeps this side looser.
            vec2 range = tileDepth[CHECKED(CHECK_SITE_TILE_DEPTH, tile, tileDepth.length())];
            if (uFromNear) range = vec2(uNear, range.y > 0.0 ? range.y : uFar);  // y = 0: nothing drawn
            float slack = 1e-5 * range.y + 1e-6;
            if (depth + r < range.x - slack || depth - r > range.y + slack) continue;
            uint slot = atomicAdd(tileBinCount[CHECKED(CHECK_SITE_TILE_BIN_COUNT, tile, tileBinCount.length())], 1u);
            if (slot < uint(uBinCap))
                tileBinLight[CHECKED(CHECK_SITE_TILE_BIN_LIGHT, tile * uint(uBinCap) + slot, tileBinLight.length())] = uint(i);
        }
}
