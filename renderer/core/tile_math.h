// Tiled lighting's geometry: the 16x16 tile grid, each tile's view-space frustum and the
// sphere-versus-tile test (depth bounds come from linearDepth(), core/depth.h). Pure math;
// shaders/lighting_tiled.comp does the same per tile.
#pragma once

#include "core/depth.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>

namespace gbl {

inline constexpr int kTileSize = 16;
// Candidate lights stored per tile by the binning pass (shaders/tile_bin.comp), at most. A tile
// reached by more keeps its true count and its work group tests every light instead (exact, slower).
inline constexpr int kTileBinMaxLights = 1024;

// The bin length that fits one storage block (GL_MAX_SHADER_STORAGE_BLOCK_SIZE, at least 16 MiB)
// for `tiles` tiles of 4-byte indices: 1024 at 1280x720 (3600 tiles, 14.1 MiB), fewer at larger
// sizes; 0 sends every tile to the test-every-light path.
inline int tileBinCap(int tiles, long long maxBlockBytes) {
    if (tiles <= 0) return kTileBinMaxLights;
    long long const fits = maxBlockBytes / (4LL * tiles);
    return int(std::clamp<long long>(fits, 0, kTileBinMaxLights));
}

// Tiles are counted from the bottom-left corner, like gl_FragCoord and compute invocation ids.
struct TileGrid {
    int tilesX = 0;
    int tilesY = 0;
    int tileSize = kTileSize;
    int count() const { return tilesX * tilesY; }
};

// Enough tiles to cover every pixel; the last row and column may be partial.
inline TileGrid tileGrid(int width, int height, int tileSize = kTileSize) {
    if (width <= 0 || height <= 0 || tileSize <= 0) return {0, 0, tileSize};
    return {(width + tileSize - 1) / tileSize, (height + tileSize - 1) / tileSize, tileSize};
}

// Half-open pixel rectangle [x0, x1) x [y0, y1), origin bottom-left.
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int area() const { return std::max(x1 - x0, 0) * std::max(y1 - y0, 0); }
};

// The pixels of tile (tx, ty), clipped to the screen.
inline PixelRect tilePixelRect(TileGrid const& g, int width, int height, int tx, int ty) {
    return {tx * g.tileSize, ty * g.tileSize, std::min((tx + 1) * g.tileSize, width),
            std::min((ty + 1) * g.tileSize, height)};
}

// The four side planes of a tile's frustum in view space, as (inward unit normal, 0): they all
// pass through the eye. A point p is inside when dot(normal, p) >= 0 for all four.
struct TileFrustum {
    std::array<glm::vec4, 4> planes{};  // left, right, bottom, top
};

// Built from the tile's corners unprojected through the inverse projection, so any perspective
// projection (symmetric or not) works.
inline TileFrustum tileFrustum(glm::mat4 const& inverseProjection, int width, int height, PixelRect const& rect) {
    auto ndcX = [width](int px) { return 2.0f * float(px) / float(width) - 1.0f; };
    auto ndcY = [height](int py) { return 2.0f * float(py) / float(height) - 1.0f; };
    auto unproject = [&](float x, float y) {
        glm::vec4 const v = inverseProjection * glm::vec4(x, y, 1.0f, 1.0f);  // on the far plane
        return glm::vec3(v) / v.w;
    };
    glm::vec3 const bl = unproject(ndcX(rect.x0), ndcY(rect.y0)), br = unproject(ndcX(rect.x1), ndcY(rect.y0));
    glm::vec3 const tl = unproject(ndcX(rect.x0), ndcY(rect.y1)), tr = unproject(ndcX(rect.x1), ndcY(rect.y1));
    glm::vec3 const centre = (bl + br + tl + tr) * 0.25f;
    // Each side plane contains the eye (origin) and one edge of the tile.
    auto plane = [&](glm::vec3 a, glm::vec3 b) {
        glm::vec3 n = glm::normalize(glm::cross(a, b));
        if (glm::dot(n, centre) < 0.0f) n = -n;  // inward
        return glm::vec4(n, 0.0f);
    };
    return {{plane(bl, tl), plane(br, tr), plane(bl, br), plane(tl, tr)}};
}

// Conservative sphere test against a tile frustum cut to the tile's depth bounds (positive view
// depths of the nearest and farthest geometry in the tile). May accept a sphere that only
// touches the frustum's corner region (the usual false positives of plane tests), never
// rejects one that reaches a pixel of the tile within the depth bounds.
inline bool sphereTouchesTile(TileFrustum const& tile, float minDepth, float maxDepth, glm::vec3 centreView,
                              float radius) {
    float const depth = -centreView.z;
    if (depth + radius < minDepth || depth - radius > maxDepth) return false;
    for (glm::vec4 const& p : tile.planes)
        if (glm::dot(glm::vec3(p), centreView) < -radius) return false;
    return true;
}

// The tiles a light is binned into (shaders/tile_bin.comp does the same per light): inclusive
// tile ranges, empty (x0 > x1) when the light cannot reach anything between near and far. A sphere
// wholly beyond the near plane is bounded by its view-space box, whose projection contains the
// sphere's (the perspective image of a convex box is the hull of its corners), widened by a pixel
// for rounding; one that crosses the near plane gets every tile. Every tile that
// sphereTouchesTile() accepts lies inside: a column passes the left and right plane tests exactly
// when the sphere's projected x extent overlaps it, and that extent lies within the box's.
struct TileRange {
    int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
    bool empty() const { return x0 > x1 || y0 > y1; }
    bool contains(int tx, int ty) const { return tx >= x0 && tx <= x1 && ty >= y0 && ty <= y1; }
};

inline TileRange sphereTileRange(glm::mat4 const& projection, int width, int height, TileGrid const& g,
                                 glm::vec3 centreView, float radius, float nearPlane, float farPlane) {
    float const depth = -centreView.z;
    if (!(radius > 0.0f) || depth + radius < nearPlane || depth - radius > farPlane || g.count() == 0) return {};
    if (!(depth - radius > nearPlane)) return {0, 0, g.tilesX - 1, g.tilesY - 1};
    glm::vec2 lo(3e38f), hi(-3e38f);
    for (int corner = 0; corner < 8; ++corner) {
        glm::vec3 const s(corner & 1 ? 1.0f : -1.0f, corner & 2 ? 1.0f : -1.0f, corner & 4 ? 1.0f : -1.0f);
        glm::vec4 const clip = projection * glm::vec4(centreView + radius * s, 1.0f);
        glm::vec2 const ndc = glm::vec2(clip) / clip.w;
        lo = glm::min(lo, ndc);
        hi = glm::max(hi, ndc);
    }
    glm::vec2 const size{float(width), float(height)}, margin{float(g.tileSize)};
    glm::vec2 const pxLo = glm::clamp((lo * 0.5f + 0.5f) * size - 1.0f, -margin, size + margin);
    glm::vec2 const pxHi = glm::clamp((hi * 0.5f + 0.5f) * size + 1.0f, -margin, size + margin);
    glm::ivec2 const t0 = glm::max(glm::ivec2(glm::floor(pxLo / float(g.tileSize))), glm::ivec2(0));
    glm::ivec2 const t1 =
        glm::min(glm::ivec2(glm::floor(pxHi / float(g.tileSize))), glm::ivec2(g.tilesX - 1, g.tilesY - 1));
    return {t0.x, t0.y, t1.x, t1.y};
}

}  // namespace gbl
