// The light binning pass (passes/tile_bins.h) on a hand-made depth buffer: a tile's bin takes
// only the lights whose depth range meets the depths its drawn pixels show (tile_depth.comp),
// so lights floating in front of a far wall, hidden behind it, or over empty background never
// fill a tile's bin.
#include "core/light_math.h"
#include "core/tile_math.h"
#include "gl/shader_library.h"
#include "gl_fixture.h"
#include "passes/tile_bins.h"

#include <glm/gtc/matrix_transform.hpp>

#include <vector>

namespace gbl {
namespace {

constexpr int kW = 64, kH = 32;  // 4 x 2 tiles of 16 pixels
constexpr float kNear = 0.1f, kFar = 100.0f;

// The window depth the geometry pass stores for view depth z (the inverse of linearDepth()).
float windowDepth(float z) {
    return kFar * (z - kNear) / (z * (kFar - kNear));
}

class TileBinsGlTest : public test::GlTest {};

TEST_F(TileBinsGlTest, ABinHoldsOnlyLightsWithinTheDepthsItsTileShows) {
    if (!caps().computeShaders) GTEST_SKIP() << "its passes are compute shaders: " << caps().tiledUnavailableReason();
    ShaderLibrary lib("");
    std::string log;
    ASSERT_TRUE(lib.add(ProgramId::TileDepth, &log)) << log;
    ASSERT_TRUE(lib.add(ProgramId::TileBin, &log)) << log;

    // A wall at view depth `wall` fills the left half of the frame; the right half is background.
    PointLight light;  // the default falloff: radius about 2 units
    float const r = lightRadius(light).radius;
    ASSERT_GT(r, 0.5f);
    float const wall = 12.0f * r;
    std::vector<float> depth(std::size_t(kW) * kH, 1.0f);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW / 2; ++x) depth[std::size_t(y) * kW + x] = windowDepth(wall);
    gl::Texture const depthTexture = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, kW, kH, "test depth");
    glBindTexture(GL_TEXTURE_2D, depthTexture.id());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kW, kH, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    glBindTexture(GL_TEXTURE_2D, 0);

    // The camera sits at the origin looking down -z; x = -halfWidth(z) / 2 is the middle of the
    // left half at depth z, +halfWidth(z) / 2 the middle of the right half.
    float const aspect = float(kW) / float(kH);
    float const tanHalf = std::tan(glm::radians(30.0f));
    auto at = [&](float side, float z) {
        PointLight l = light;
        l.position = glm::vec3(side * 0.5f * tanHalf * aspect * z, 0.0f, -z);
        return l;
    };
    std::vector<PointLight> const lights{
        at(-1.0f, wall),             // 0: at the wall: a candidate of the wall's tiles
        at(-1.0f, wall - 3.0f * r),  // 1: floating in front of the wall, reaching none of it
        at(-1.0f, wall + 3.0f * r),  // 2: hidden behind the wall
        at(+1.0f, wall),             // 3: over the background: no drawn pixel to reach
    };
    LightBuffer buffer;
    ASSERT_FALSE(buffer.upload(lights, caps()).has_value());

    TileBins bins;
    tileBinPass({{lib.get(ProgramId::TileDepth), lib.get(ProgramId::TileBin)}, buffer, depthTexture, bins, caps()},
                {glm::mat4(1.0f), glm::perspective(glm::radians(60.0f), aspect, kNear, kFar), kW, kH, kNear, kFar});
    TileGrid const grid = tileGrid(kW, kH);
    ASSERT_EQ(bins.tiles, grid.count());
    std::vector<GLuint> counts(std::size_t(grid.count()));
    std::vector<GLuint> entries(std::size_t(grid.count()) * std::size_t(bins.cap));
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, bins.counts.id());
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(counts.size() * sizeof(GLuint)), counts.data());
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, bins.lights.id());
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(entries.size() * sizeof(GLuint)), entries.data());
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);

    int wallTilesWithLight0 = 0;
    for (int ty = 0; ty < grid.tilesY; ++ty)
        for (int tx = 0; tx < grid.tilesX; ++tx) {
            int const tile = ty * grid.tilesX + tx;
            GLuint const n = counts[std::size_t(tile)];
            if (tx >= grid.tilesX / 2) {
                EXPECT_EQ(n, 0u) << "background tile " << tx << "," << ty << " holds lights";
                continue;
            }
            ASSERT_LE(n, 1u) << "wall tile " << tx << "," << ty << " holds lights that reach none of its pixels";
            if (n == 1) {
                EXPECT_EQ(entries[std::size_t(tile) * std::size_t(bins.cap)], 0u);
                ++wallTilesWithLight0;
            }
        }
    EXPECT_GT(wallTilesWithLight0, 0) << "the light at the wall was binned nowhere";
}

}  // namespace
}  // namespace gbl
