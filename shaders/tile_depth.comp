// Light binning, step 0 (OpenGL 4.3): the view-depth range of each 16x16 tile's drawn pixels, so
// the binning pass (tile_bin.comp) leaves out of a tile's bin the lights wholly in front of or
// behind everything the tile shows. Without it, a tile looking far across the scene collects
// every small light along its line of sight, overflows its bin, and its pixels then test every
// light (the slow exact path of lighting_tiled.comp and cluster_shade.comp).
#version 430 core
#include "bindings.glsl"
#include "shader_checks.glsl"
#include "depth.glsl"

layout(local_size_x = GBL_TILE_SIZE, local_size_y = GBL_TILE_SIZE) in;  // GBL_TILE_SIZE: kTileSize, core/tile_math.h

#define TILE_DEPTH_ACCESS writeonly
#include "tile_depth_buffer.glsl"

uniform sampler2D uDepth;
uniform ivec2 uScreenSize;
uniform float uNear;
uniform float uFar;

shared uint sMinDepthBits;  // positive floats order like their bits
shared uint sMaxDepthBits;

void main() {
    if (gl_LocalInvocationIndex == 0u) {
        sMinDepthBits = floatBitsToUint(3.0e38);
        sMaxDepthBits = 0u;
    }
    memoryBarrierShared();
    barrier();
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (px.x < uScreenSize.x && px.y < uScreenSize.y) {
        float d = texelFetch(uDepth, px, 0).r;
        if (d < 1.0) {  // drawn: the geometry pass clears depth to 1 and draws with GL_LESS
            float viewDepth = linearDepth(d, uNear, uFar);
            atomicMin(sMinDepthBits, floatBitsToUint(viewDepth));
            atomicMax(sMaxDepthBits, floatBitsToUint(viewDepth));
        }
    }
    memoryBarrierShared();
    barrier();
    if (gl_LocalInvocationIndex == 0u)
        tileDepth[CHECKED(CHECK_SITE_TILE_DEPTH, gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x, tileDepth.length())] =
            vec2(uintBitsToFloat(sMinDepthBits), uintBitsToFloat(sMaxDepthBits));
}
