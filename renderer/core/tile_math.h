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

}  // namespace gbl
