// Tiled and clustered lists built from the light bins (shaders/tile_bin.comp) with thousands of
// small lights, and with a tile holding more candidates than the bins keep: both still add
// exactly the lights the full-screen pass adds, in its order.
#include "core/cluster_math.h"
#include "core/light_math.h"
#include "core/tile_math.h"
#include "gl_fixture.h"
#include "scene/default_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace gbl;
using gbl::test::GlTest;

namespace {

constexpr int kW = 160, kH = 90;  // quad visits every light at every pixel: a small frame

// fp16 rounding of the lit target: 2^-11 relative per stored value.
constexpr double kHalfUlp = 1.0 / 2048.0;

PipelineSettings settingsFor(LightingMode mode, DebugView view = DebugView::Final) {
    PipelineSettings s;
    s.mode = mode;
    s.view = view;
    s.lightCubes = false;  // the lighting alone
    return s;
}

// bench's --radius-scale: Kl / s and Kq / s^2 scale every radius by exactly s.
std::vector<PointLight> smallLights(int count, float s) {
    std::vector<PointLight> lights = makeDefaultLights(count);
    for (auto& l : lights) {
        l.kl /= s;
        l.kq /= s * s;
    }
    return lights;
}

class ManyLightsGlTest : public test::CourtyardGlTest {
protected:
    explicit ManyLightsGlTest(int width = kW, int height = kH) : CourtyardGlTest(width, height, true) {}
    FloatImage lighting(LightingMode m, std::span<PointLight const> lights) {
        FrameStats const st = renderer_->render({camera_, lights, settingsFor(m), true});
        EXPECT_EQ(st.modeUsed, m) << st.fallbackReason;
        EXPECT_EQ(st.glErrors, 0u);
        return renderer_->readAttachment(Attachment::Lighting);
    }
    // Lights that lit each pixel (the heat map's y count).
    std::vector<float> litCounts(LightingMode m, std::span<PointLight const> lights) {
        renderer_->render({camera_, lights, settingsFor(m, DebugView::Heatmap), true});
        FloatImage const img = renderer_->readAttachment(Attachment::Coverage);
        std::vector<float> out;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) out.push_back(img.at(x, y, 1));
        return out;
    }
    // Every culled mode against quad: each pixel's light count equal, its colour within the bound.
    void expectTiledAndClusteredMatchQuad(std::span<PointLight const> lights, int minLitPixels) {
        FloatImage const quad = lighting(LightingMode::Quad, lights);
        std::vector<float> const quadLit = litCounts(LightingMode::Quad, lights);
        int litPixels = 0;
        for (float c : quadLit) litPixels += c > 0.0f;
        ASSERT_GE(litPixels, minLitPixels) << "the lights should reach the scene's surfaces";
        for (LightingMode m : {LightingMode::Tiled, LightingMode::Clustered}) {
            char const* name = m == LightingMode::Tiled ? "tiled" : "clustered";
            // The same lights in the same order in fp32, stored once to fp16: one rounding (2
            // half-ulps) plus slack for the compiler fusing differently, as light_modes_gl_test.
            FloatImage const img = lighting(m, lights);
            int over = 0;
            double worst = 0.0;
            for (std::size_t i = 0; i < quad.pixels.size(); ++i) {
                if (i % 4 == 3) continue;  // alpha
                double const e = std::abs(double(img.pixels[i]) - quad.pixels[i]);
                worst = std::max(worst, e);
                over += e > 4 * kHalfUlp * std::abs(quad.pixels[i]) + 1e-5;
            }
            EXPECT_EQ(over, 0) << name << ": largest difference " << worst;
            // A light missing from a list shows as one light fewer at the pixels it reaches.
            std::vector<float> const lit = litCounts(m, lights);
            int differ = 0;
            for (std::size_t i = 0; i < lit.size(); ++i) differ += lit[i] != quadLit[i];
            EXPECT_EQ(differ, 0) << name << ": pixels whose lit-light count differs from quad's";
        }
    }
};

}  // namespace

TEST_F(ManyLightsGlTest, ThousandsOfSmallLightsMatchQuad) {
    // bench's --radius-scale auto at 4096 lights: s = sqrt(32 / 4096), radii around 0.4 units, so
    // each light covers a few tiles and the bins, not the every-light path, build the lists.
    std::vector<PointLight> const lights = smallLights(4096, std::sqrt(32.0f / 4096.0f));
    expectTiledAndClusteredMatchQuad(lights, kW * kH / 20);
}

TEST_F(ManyLightsGlTest, TilesOverTheBinCapTestEveryLightAndStillMatchQuad) {
    // kTileBinMaxLights + 100 copies of one light fill its tiles' bins past the cap (those tiles
    // take the every-light path); the scene's 32 lights around them go through the bins.
    std::vector<PointLight> lights = makeDefaultLights(32);
    PointLight const crowd = lights[5];
    lights.insert(lights.begin() + 3, std::size_t(kTileBinMaxLights + 100), crowd);
    expectTiledAndClusteredMatchQuad(lights, kW * kH / 4);
}

TEST_F(ManyLightsGlTest, ClustersOverTheirCapShadeFromTheTileListAndStillMatchQuad) {
    // kClusterMaxLights + 44 copies of one light: its clusters are over their list cap (they shade
    // from their tile's sorted list), while the tiles' bins (up to 1024) still hold them.
    std::vector<PointLight> lights = makeDefaultLights(32);
    PointLight const crowd = lights[9];
    lights.insert(lights.begin() + 7, std::size_t(kClusterMaxLights + 44), crowd);
    expectTiledAndClusteredMatchQuad(lights, kW * kH / 4);
}

namespace {
// Every pixel of quad visits every light: 70,000 of them want a tiny frame.
constexpr int kTinyW = 48, kTinyH = 27;
class TinyFrameManyLightsGlTest : public ManyLightsGlTest {
protected:
    TinyFrameManyLightsGlTest() : ManyLightsGlTest(kTinyW, kTinyH) {}
};
}  // namespace

TEST_F(TinyFrameManyLightsGlTest, MoreLightsThanOneShaderMayLoopOver) {
    // llvmpipe ends a shader invocation's loops after 65,535 iterations in all (light_fetch.glsl,
    // LIGHTS_PER_ITERATION). 70,000 lights below the ground, past the far plane (they reach no
    // pixel and no tile), come before kTileBinMaxLights + 100 copies of one scene light: quad
    // loops over all of them at every pixel, and the copies' tiles overflow their bins and
    // their clusters their lists, so clustered's pixels there loop over every light as well. A
    // loop that stopped early would drop the copies, which all come after the 65,535th light.
    std::vector<PointLight> lights = makeDefaultLights(32);
    PointLight below = lights[0];
    below.position.y = -1000.0f;
    lights.insert(lights.end(), 70000, below);
    PointLight const crowd = lights[5];
    std::size_t const firstCopy = lights.size();
    lights.insert(lights.end(), std::size_t(kTileBinMaxLights + 100), crowd);
    ASSERT_GT(firstCopy, 65535u);
    std::vector<float> const quadLit = litCounts(LightingMode::Quad, lights);
    float const most = *std::max_element(quadLit.begin(), quadLit.end());
    EXPECT_GE(most, float(kTileBinMaxLights + 100)) << "every copy of the crowded light reaches the surface under it";
    expectTiledAndClusteredMatchQuad(lights, kTinyW * kTinyH / 4);
}
