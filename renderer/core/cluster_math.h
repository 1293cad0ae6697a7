// Clustered lighting's geometry: screen tiles split into exponential view-depth slices, each cluster's
// view-space bounding box and the sphere-versus-box test. Pure math; shaders/cluster_build.comp and
// cluster_shade.comp do the same per cluster and per pixel.
#pragma once

#include "core/tile_math.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace gbl {

inline constexpr int kClusterTileSize = kTileSize;  // pixels: tiled mode's tiles (GBL_TILE_SIZE in the shaders)
inline constexpr int kClusterSlices = 24;           // exponential depth slices between near and far
// Lights stored per cluster, at most. A cluster reached by more keeps its true count, and its
// pixels loop over every light (exact, slower) instead of the list: the cap costs time, never
// correctness. 256 holds the default scene's 512 lights at their full radii.
inline constexpr int kClusterMaxLights = 256;

// The list length that fits one storage block (GL_MAX_SHADER_STORAGE_BLOCK_SIZE: 16 MiB is all GL
// 4.3 guarantees, llvmpipe gives 128 MiB) for `clusters` clusters of 4-byte indices: 256 at
// 1280x720 on llvmpipe, fewer at larger sizes; 0 makes every pixel loop over every light.
inline int clusterListCap(int clusters, long long maxBlockBytes) {
    if (clusters <= 0) return kClusterMaxLights;
    long long const fits = maxBlockBytes / (4LL * clusters);
    return int(std::clamp<long long>(fits, 0, kClusterMaxLights));
}

struct ClusterGrid {
    int tilesX = 0;
    int tilesY = 0;
    int slices = kClusterSlices;
    int count() const { return tilesX * tilesY * slices; }
    // Cluster index as the shaders store it: x fastest, then y, then slice.
    int index(int tx, int ty, int slice) const { return (slice * tilesY + ty) * tilesX + tx; }
};

inline ClusterGrid clusterGrid(int width, int height, int slices = kClusterSlices) {
    TileGrid const t = tileGrid(width, height, kClusterTileSize);
    return {t.tilesX, t.tilesY, slices};
}

// Slice k covers view depths [near * (far/near)^(k/S), near * (far/near)^((k+1)/S)): equal ratios,
// so near slices are thin where perspective packs pixels densely in depth.
inline float clusterSliceNear(int slice, float nearPlane, float farPlane, int slices = kClusterSlices) {
    return nearPlane * std::pow(farPlane / nearPlane, float(slice) / float(slices));
}

// The slice holding view depth `depth` (positive, distance along -Z), clamped to the grid.
inline int clusterSlice(float depth, float nearPlane, float farPlane, int slices = kClusterSlices) {
    if (!(depth > nearPlane)) return 0;
    float const s = std::log(depth / nearPlane) / std::log(farPlane / nearPlane) * float(slices);
    return std::clamp(int(std::floor(s)), 0, slices - 1);
}

// The depth-slice view (DebugView::ClusterSlices, shaders/view.frag sliceColor is the twin): slice
// k's colour, hues a golden-ratio turn apart, every other slice darker, so neighbours always differ.
inline glm::vec3 clusterSliceColor(int slice) {
    float const h = glm::fract(float(slice) * 0.618034f);
    glm::vec3 const k =
        glm::clamp(glm::abs(glm::fract(glm::vec3(h) + glm::vec3(1.0f, 2.0f / 3.0f, 1.0f / 3.0f)) * 6.0f - 3.0f) - 1.0f,
                   0.0f, 1.0f);
    return (slice % 2 == 0 ? 1.0f : 0.6f) * glm::mix(glm::vec3(1.0f), k, 0.75f);
}
// Width in texels of a slice's swatch in that view's legend (SLICE_SWATCH in shaders/view_constants.glsl).
inline constexpr int kSliceSwatchTexels = 12;

struct ViewBox {
    glm::vec3 lo{0.0f};
    glm::vec3 hi{0.0f};
};

// The view-space box around cluster (tx, ty, slice): the tile's four corner rays, cut at the
// slice's near and far depths. Any point of the cluster's frustum piece lies inside it.
inline ViewBox clusterViewBox(glm::mat4 const& inverseProjection, int width, int height, ClusterGrid const& g, int tx,
                              int ty, int slice, float nearPlane, float farPlane) {
    TileGrid const t{g.tilesX, g.tilesY, kClusterTileSize};
    PixelRect const r = tilePixelRect(t, width, height, tx, ty);
    float const d0 = clusterSliceNear(slice, nearPlane, farPlane, g.slices);
    float const d1 = clusterSliceNear(slice + 1, nearPlane, farPlane, g.slices);
    ViewBox b{glm::vec3(3e38f), glm::vec3(-3e38f)};
    for (int corner = 0; corner < 4; ++corner) {
        float const x = 2.0f * float(corner & 1 ? r.x1 : r.x0) / float(width) - 1.0f;
        float const y = 2.0f * float(corner & 2 ? r.y1 : r.y0) / float(height) - 1.0f;
        glm::vec4 const v = inverseProjection * glm::vec4(x, y, 1.0f, 1.0f);
        glm::vec3 const ray = glm::vec3(v) / v.w / (-glm::vec3(v).z / v.w);  // the point at view depth 1
        for (float d : {d0, d1}) {
            b.lo = glm::min(b.lo, ray * d);
            b.hi = glm::max(b.hi, ray * d);
        }
    }
    return b;
}

// Whether a sphere (view-space centre, radius) reaches the box: squared distance to the box.
inline bool sphereTouchesBox(glm::vec3 const& centre, float radius, ViewBox const& b) {
    if (!(radius > 0.0f)) return false;
    glm::vec3 const q = glm::clamp(centre, b.lo, b.hi);
    glm::vec3 const d = centre - q;
    return glm::dot(d, d) <= radius * radius;
}

}  // namespace gbl
