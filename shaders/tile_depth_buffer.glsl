// Each tile's view-depth range of drawn pixels: x the nearest, y the farthest; (3e38, 0) when the
// tile has none. tile_depth.comp writes it (defining TILE_DEPTH_ACCESS as writeonly); tile_bin.comp
// and lighting_tiled.comp read it.
#ifndef GBL_TILE_DEPTH_BUFFER_GLSL
#define GBL_TILE_DEPTH_BUFFER_GLSL
#ifndef TILE_DEPTH_ACCESS
#define TILE_DEPTH_ACCESS readonly
#endif
layout(std430, binding = BIND_SSBO_TILE_DEPTH) TILE_DEPTH_ACCESS buffer TileDepth { vec2 tileDepth[]; };
#endif
