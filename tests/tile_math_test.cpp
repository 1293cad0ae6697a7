// Tile grid, tile frusta and the sphere-versus-tile test against analytic cases.
#include "core/tile_math.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <random>

using namespace gbl;

TEST(TileGrid, CoversEveryPixel) {
    TileGrid g = tileGrid(1280, 720);
    EXPECT_EQ(g.tilesX, 80);  // 1280 / 16
    EXPECT_EQ(g.tilesY, 45);  // 720 / 16
    EXPECT_EQ(g.count(), 3600);
    g = tileGrid(1281, 721);  // one more pixel each way needs a partial tile
    EXPECT_EQ(g.tilesX, 81);
    EXPECT_EQ(g.tilesY, 46);
    g = tileGrid(15, 1);
    EXPECT_EQ(g.tilesX, 1);
    EXPECT_EQ(g.tilesY, 1);
    EXPECT_EQ(tileGrid(0, 0).count(), 0);  // a minimised window has no tiles
    EXPECT_EQ(tileGrid(-4, 100).count(), 0);
}

TEST(TileGrid, LastTileIsClippedToTheScreen) {
    TileGrid const g = tileGrid(40, 20);  // 3 x 2 tiles
    PixelRect const last = tilePixelRect(g, 40, 20, 2, 1);
    EXPECT_EQ(last.x0, 32);
    EXPECT_EQ(last.x1, 40);
    EXPECT_EQ(last.y0, 16);
    EXPECT_EQ(last.y1, 20);
    EXPECT_EQ(last.area(), 8 * 4);
    int total = 0;
    for (int ty = 0; ty < g.tilesY; ++ty)
        for (int tx = 0; tx < g.tilesX; ++tx) total += tilePixelRect(g, 40, 20, tx, ty).area();
    EXPECT_EQ(total, 40 * 20);
}

TEST(TileFrustum, QuadrantTilesOfA90DegreeCameraHaveAnalyticPlanes) {
    // fov 90 and aspect 1: the screen edges are the planes x = +-(-z) and y = +-(-z). On a 32x32
    // screen in 16x16 tiles, tile (1, 1) is the top-right quadrant: x >= 0, y >= 0, x <= -z, y <= -z.
    glm::mat4 const proj = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f);
    TileGrid const g = tileGrid(32, 32);
    TileFrustum const t = tileFrustum(glm::inverse(proj), 32, 32, tilePixelRect(g, 32, 32, 1, 1));
    float const s = std::sqrt(0.5f);
    glm::vec3 const expected[4] = {{1, 0, 0}, {-s, 0, -s}, {0, 1, 0}, {0, -s, -s}};  // left, right, bottom, top
    for (int i = 0; i < 4; ++i) {
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(t.planes[i][c], expected[i][c], 1e-5) << "plane " << i << " c " << c;
        EXPECT_EQ(t.planes[i].w, 0.0f);
    }
}

TEST(TileFrustum, SphereAgainstQuadrantTiles) {
    glm::mat4 const proj = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f);
    glm::mat4 const inv = glm::inverse(proj);
    TileGrid const g = tileGrid(32, 32);
    auto tile = [&](int tx, int ty) { return tileFrustum(inv, 32, 32, tilePixelRect(g, 32, 32, tx, ty)); };
    float const nearD = 0.1f, farD = 100.0f;

    // Centred on the view axis: touches all four quadrants.
    for (int ty = 0; ty < 2; ++ty)
        for (int tx = 0; tx < 2; ++tx) EXPECT_TRUE(sphereTouchesTile(tile(tx, ty), nearD, farD, {0, 0, -10}, 1.0f));
    // Well inside the top-right quadrant: only tile (1, 1).
    EXPECT_TRUE(sphereTouchesTile(tile(1, 1), nearD, farD, {5, 5, -10}, 1.0f));
    EXPECT_FALSE(sphereTouchesTile(tile(0, 1), nearD, farD, {5, 5, -10}, 1.0f));
    EXPECT_FALSE(sphereTouchesTile(tile(1, 0), nearD, farD, {5, 5, -10}, 1.0f));
    EXPECT_FALSE(sphereTouchesTile(tile(0, 0), nearD, farD, {5, 5, -10}, 1.0f));
    // Centre 0.5 left of the x = 0 plane with radius 1: reaches into the right-hand tiles too;
    // with radius 0.4 it does not.
    EXPECT_TRUE(sphereTouchesTile(tile(1, 1), nearD, farD, {-0.5f, 3, -10}, 1.0f));
    EXPECT_TRUE(sphereTouchesTile(tile(0, 1), nearD, farD, {-0.5f, 3, -10}, 1.0f));
    EXPECT_FALSE(sphereTouchesTile(tile(1, 1), nearD, farD, {-0.5f, 3, -10}, 0.4f));
    // Behind the camera: no tile.
    EXPECT_FALSE(sphereTouchesTile(tile(1, 1), nearD, farD, {1, 1, 10}, 1.0f));
    // Camera inside the sphere: every tile.
    for (int ty = 0; ty < 2; ++ty)
        for (int tx = 0; tx < 2; ++tx)
            EXPECT_TRUE(sphereTouchesTile(tile(tx, ty), nearD, farD, {0.2f, -0.3f, 0.5f}, 2.0f));
}

TEST(TileFrustum, DepthBoundsCutTheTile) {
    glm::mat4 const proj = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f);
    TileGrid const g = tileGrid(32, 32);
    TileFrustum const t = tileFrustum(glm::inverse(proj), 32, 32, tilePixelRect(g, 32, 32, 1, 1));
    // Geometry in the tile lies between depths 5 and 8.
    EXPECT_FALSE(sphereTouchesTile(t, 5.0f, 8.0f, {1, 1, -10}, 1.0f));   // nearest point at 9
    EXPECT_TRUE(sphereTouchesTile(t, 5.0f, 8.0f, {1, 1, -10}, 2.5f));    // reaches 7.5
    EXPECT_FALSE(sphereTouchesTile(t, 5.0f, 8.0f, {1, 1, -3}, 1.5f));    // farthest point at 4.5
    EXPECT_TRUE(sphereTouchesTile(t, 5.0f, 8.0f, {1, 1, -3}, 2.5f));     // reaches 5.5
    EXPECT_TRUE(sphereTouchesTile(t, 5.0f, 8.0f, {1, 1, -6.5f}, 0.1f));  // between the bounds
}

TEST(TileFrustum, NeverMissesASphereOverItsPixelsAndRejectsFarTiles) {
    // Random small spheres anywhere in an asymmetric-aspect frustum: the tile holding the
    // projected centre must accept; tiles two or more tiles away must reject (the sphere is far
    // smaller than a tile at these depths, so the plane test's false positives cannot reach).
    int const w = 320, h = 180;
    glm::mat4 const proj = glm::perspective(glm::radians(60.0f), float(w) / h, 0.1f, 200.0f);
    glm::mat4 const inv = glm::inverse(proj);
    TileGrid const g = tileGrid(w, h);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), depthDist(1.0f, 50.0f);
    int accepted = 0, rejected = 0;
    for (int i = 0; i < 500; ++i) {
        float const d = depthDist(rng);
        glm::vec4 v = inv * glm::vec4(u(rng) * 0.98f, u(rng) * 0.98f, 1.0f, 1.0f);
        glm::vec3 const p = glm::vec3(v) / v.w * (d / -(v.z / v.w));
        float const radius = 1e-4f * d;  // well under a pixel
        glm::vec4 const clip = proj * glm::vec4(p, 1.0f);
        int const px = int((clip.x / clip.w * 0.5f + 0.5f) * w), py = int((clip.y / clip.w * 0.5f + 0.5f) * h);
        int const ctx = px / kTileSize, cty = py / kTileSize;
        for (int ty = 0; ty < g.tilesY; ++ty) {
            for (int tx = 0; tx < g.tilesX; ++tx) {
                bool const hit =
                    sphereTouchesTile(tileFrustum(inv, w, h, tilePixelRect(g, w, h, tx, ty)), 0.1f, 200.0f, p, radius);
                if (tx == ctx && ty == cty) {
                    ASSERT_TRUE(hit) << "sphere " << i << " missed by its own tile";
                    ++accepted;
                } else if (std::abs(tx - ctx) >= 2 || std::abs(ty - cty) >= 2) {
                    ASSERT_FALSE(hit) << "sphere " << i << " in far tile " << tx << "," << ty;
                    ++rejected;
                }
            }
        }
    }
    EXPECT_EQ(accepted, 500);
    EXPECT_GT(rejected, 500 * 100);
}

TEST(TileBins, SphereTileRangeHoldsEveryTileThePlaneTestAccepts) {
    // The binning pass stores a light only in the tiles of sphereTileRange(); the tiled and
    // clustered lists then keep those that pass sphereTouchesTile(). The lists equal the plane
    // test's alone (and so stay exact) only if no accepted tile lies outside the range: checked
    // for spheres of every size, near the eye, crossing the near plane and past the screen edges.
    int const w = 320, h = 180;
    float const nearP = 0.1f, farP = 200.0f;
    glm::mat4 const proj = glm::perspective(glm::radians(60.0f), float(w) / h, nearP, farP);
    glm::mat4 const inv = glm::inverse(proj);
    TileGrid const g = tileGrid(w, h);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.3f, 1.3f), depthDist(-2.0f, 60.0f), radiusDist(0.0f, 1.0f);
    int accepted = 0, outsideRange = 0;
    long long rangeTiles = 0, allTiles = 0;
    for (int i = 0; i < 400; ++i) {
        float const d = depthDist(rng);
        glm::vec3 const p(u(rng) * std::abs(d) * 0.7f, u(rng) * std::abs(d) * 0.4f, -d);
        float const radius = std::pow(radiusDist(rng), 3.0f) * 8.0f + 1e-3f;
        TileRange const range = sphereTileRange(proj, w, h, g, p, radius, nearP, farP);
        for (int ty = 0; ty < g.tilesY; ++ty)
            for (int tx = 0; tx < g.tilesX; ++tx) {
                bool const hit =
                    sphereTouchesTile(tileFrustum(inv, w, h, tilePixelRect(g, w, h, tx, ty)), nearP, farP, p, radius);
                accepted += hit;
                outsideRange += hit && !range.contains(tx, ty);
                rangeTiles += range.contains(tx, ty);
                ++allTiles;
            }
    }
    EXPECT_EQ(outsideRange, 0);
    EXPECT_GT(accepted, 1000);
    // ...and the ranges are what makes binning pay: far fewer tiles than all of them.
    EXPECT_LT(rangeTiles * 4, allTiles);
}

TEST(TileBins, RangeOfASmallSphereIsItsTileAndEmptyPastTheFarPlane) {
    int const w = 320, h = 180;
    glm::mat4 const proj = glm::perspective(glm::radians(90.0f), float(w) / h, 0.1f, 100.0f);
    TileGrid const g = tileGrid(w, h);  // 20 x 12 tiles
    // On the view axis: the centre pixel (160, 90) is the corner of tiles 9..10 and 5 (90 / 16 = 5.6).
    TileRange const r = sphereTileRange(proj, w, h, g, {0.0f, 0.0f, -10.0f}, 0.01f, 0.1f, 100.0f);
    EXPECT_EQ(r.x0, 9);
    EXPECT_EQ(r.x1, 10);
    EXPECT_EQ(r.y0, 5);
    EXPECT_EQ(r.y1, 5);
    EXPECT_TRUE(sphereTileRange(proj, w, h, g, {0.0f, 0.0f, -120.0f}, 1.0f, 0.1f, 100.0f).empty());
    EXPECT_TRUE(sphereTileRange(proj, w, h, g, {0.0f, 0.0f, 5.0f}, 1.0f, 0.1f, 100.0f).empty());   // behind the eye
    EXPECT_TRUE(sphereTileRange(proj, w, h, g, {0.0f, 0.0f, -5.0f}, 0.0f, 0.1f, 100.0f).empty());  // radius 0
    // Crossing the near plane: every tile.
    TileRange const all = sphereTileRange(proj, w, h, g, {0.0f, 0.0f, -0.5f}, 1.0f, 0.1f, 100.0f);
    EXPECT_EQ(all.x0, 0);
    EXPECT_EQ(all.y0, 0);
    EXPECT_EQ(all.x1, 19);
    EXPECT_EQ(all.y1, 11);
}

TEST(TileBins, CapFitsOneStorageBlock) {
    int const tiles = tileGrid(1280, 720).count();  // 3600
    EXPECT_EQ(tileBinCap(tiles, 128LL << 20), kTileBinMaxLights);
    EXPECT_EQ(tileBinCap(tiles, 16LL << 20), kTileBinMaxLights);           // 16,777,216 / 14,400 = 1165
    EXPECT_EQ(tileBinCap(tileGrid(3840, 2160).count(), 16LL << 20), 129);  // 16,777,216 / (4 * 32,400)
    EXPECT_EQ(tileBinCap(tiles, 100), 0);
    EXPECT_EQ(tileBinCap(0, 100), kTileBinMaxLights);
}
