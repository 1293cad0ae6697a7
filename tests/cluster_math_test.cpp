// Clustered lighting's CPU twin: exponential slices, cluster boxes that hold their frustum piece, sphere-box tests.
#include "core/cluster_math.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

using namespace gbl;

TEST(ClusterMath, GridCoversTheScreenInTilesAndSlices) {
    ClusterGrid const g = clusterGrid(1280, 720);
    EXPECT_EQ(g.tilesX, 80);
    EXPECT_EQ(g.tilesY, 45);
    EXPECT_EQ(g.slices, kClusterSlices);
    EXPECT_EQ(g.count(), 80 * 45 * kClusterSlices);
    ClusterGrid const odd = clusterGrid(100, 17);  // partial last tiles count
    EXPECT_EQ(odd.tilesX, 7);
    EXPECT_EQ(odd.tilesY, 2);
    EXPECT_EQ(g.index(0, 0, 0), 0);
    EXPECT_EQ(g.index(79, 44, kClusterSlices - 1), g.count() - 1);
    EXPECT_EQ(g.index(1, 0, 0), 1);
    EXPECT_EQ(g.index(0, 1, 0), 80);
}

TEST(ClusterMath, SlicesAreExponentialBetweenNearAndFar) {
    float const n = 0.1f, f = 100.0f;
    EXPECT_FLOAT_EQ(clusterSliceNear(0, n, f), n);
    EXPECT_NEAR(clusterSliceNear(kClusterSlices, n, f), f, 1e-3f);
    // Equal ratios: (far/near)^(1/24) = 1000^(1/24) = 1.3335 per slice.
    float const ratio = std::pow(f / n, 1.0f / float(kClusterSlices));
    for (int k = 0; k + 1 < kClusterSlices; ++k)
        EXPECT_NEAR(clusterSliceNear(k + 1, n, f) / clusterSliceNear(k, n, f), ratio, 1e-4f) << k;
    // A depth just inside slice k maps back to k; the ends clamp.
    for (int k = 0; k < kClusterSlices; ++k) {
        float const mid = std::sqrt(clusterSliceNear(k, n, f) * clusterSliceNear(k + 1, n, f));
        EXPECT_EQ(clusterSlice(mid, n, f), k);
    }
    EXPECT_EQ(clusterSlice(0.01f, n, f), 0);
    EXPECT_EQ(clusterSlice(1000.0f, n, f), kClusterSlices - 1);
    EXPECT_EQ(clusterSlice(1.0f, n, f), 8);  // log(10) / log(1000) * 24 = 8 exactly
}

TEST(ClusterMath, ClusterBoxHoldsEveryPointOfItsFrustumPiece) {
    int const w = 320, h = 180;
    float const n = 0.1f, f = 100.0f;
    glm::mat4 const proj = glm::perspective(glm::radians(60.0f), float(w) / float(h), n, f);
    glm::mat4 const inv = glm::inverse(proj);
    ClusterGrid const g = clusterGrid(w, h);
    for (int tx : {0, 7, g.tilesX - 1})
        for (int ty : {0, 5, g.tilesY - 1})
            for (int slice : {0, 9, kClusterSlices - 1}) {
                ViewBox const b = clusterViewBox(inv, w, h, g, tx, ty, slice, n, f);
                float const d0 = clusterSliceNear(slice, n, f), d1 = clusterSliceNear(slice + 1, n, f);
                // Pixel centres of the tile at depths through the slice, unprojected as a shader does.
                for (int px = tx * 16; px < std::min(tx * 16 + 16, w); px += 5)
                    for (int py = ty * 16; py < std::min(ty * 16 + 16, h); py += 5)
                        for (float t : {0.01f, 0.5f, 0.99f}) {
                            float const d = d0 + (d1 - d0) * t;
                            glm::vec4 v = inv * glm::vec4(2.0f * (px + 0.5f) / w - 1.0f, 2.0f * (py + 0.5f) / h - 1.0f,
                                                          1.0f, 1.0f);
                            glm::vec3 ray = glm::vec3(v) / v.w;
                            glm::vec3 const p = ray / -ray.z * d;
                            float const eps = 1e-4f * d;
                            EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, b.lo - eps)) &&
                                        glm::all(glm::lessThanEqual(p, b.hi + eps)))
                                << tx << "," << ty << "," << slice;
                            EXPECT_EQ(clusterSlice(d, n, f), slice);  // and the pixel finds this cluster
                        }
                // Its depth range is the slice's.
                EXPECT_NEAR(-b.hi.z, d0, 1e-4f * d0);
                EXPECT_NEAR(-b.lo.z, d1, 1e-4f * d1);
            }
}

TEST(ClusterMath, SphereTouchesBoxByDistanceToTheBox) {
    ViewBox const b{{-1.0f, -1.0f, -3.0f}, {1.0f, 1.0f, -2.0f}};
    EXPECT_TRUE(sphereTouchesBox({0.0f, 0.0f, -2.5f}, 0.1f, b));   // centre inside
    EXPECT_TRUE(sphereTouchesBox({2.0f, 0.0f, -2.5f}, 1.0f, b));   // touches the x face exactly
    EXPECT_FALSE(sphereTouchesBox({2.1f, 0.0f, -2.5f}, 1.0f, b));  // just short
    // Corner: distance to (1, 1, -2) is sqrt(3) * 0.5 = 0.866.
    EXPECT_TRUE(sphereTouchesBox({1.5f, 1.5f, -1.5f}, 0.87f, b));
    EXPECT_FALSE(sphereTouchesBox({1.5f, 1.5f, -1.5f}, 0.86f, b));
    EXPECT_FALSE(sphereTouchesBox({0.0f, 0.0f, -2.5f}, 0.0f, b));  // radius 0 lights shade nothing
}

TEST(ClusterMath, ListCapFitsOneStorageBlock) {
    int const clusters = clusterGrid(1280, 720).count();                  // 86,400
    EXPECT_EQ(clusterListCap(clusters, 128LL << 20), kClusterMaxLights);  // 134,217,728 / 345,600 = 388
    int const big = clusterGrid(3840, 2160).count();                      // 240 x 135 x 24 = 777,600
    EXPECT_EQ(clusterListCap(big, 128LL << 20), 43);                      // 134,217,728 / 3,110,400
    EXPECT_EQ(clusterListCap(big, 16LL << 20), 5);
    EXPECT_EQ(clusterListCap(clusters, 100), 0);  // too small for one entry: every pixel loops over all
    EXPECT_EQ(clusterListCap(0, 100), kClusterMaxLights);
}
