// The depth-slice view (DebugView::ClusterSlices): every surface pixel shows the colour of the
// exponential slice that core/cluster_math.h puts its view depth in, and the legend along the
// bottom shows every slice's colour in order.
#include "core/cluster_math.h"
#include "core/depth.h"
#include "gl_fixture.h"
#include "scene/default_scene.h"

#include <cmath>
#include <set>

using namespace gbl;
using gbl::test::GlTest;

namespace {

constexpr int kW = 320, kH = 180;

// The display target is RGBA8: a colour comes back within half a step of 1/255 of the float the
// shader wrote; CPU and GPU palettes may also differ in the last float bit before rounding.
constexpr float kColourTolerance = 1.5f / 255.0f;

glm::vec3 rgbAt(FloatImage const& img, int x, int row) {
    return {img.at(x, row, 0), img.at(x, row, 1), img.at(x, row, 2)};
}

int nearestSlice(glm::vec3 c) {
    int best = -1;
    float bestD = 1e30f;
    for (int k = 0; k < kClusterSlices; ++k) {
        glm::vec3 const d = c - clusterSliceColor(k);
        if (glm::dot(d, d) < bestD) bestD = glm::dot(d, d), best = k;
    }
    return best;
}

class ClusterSlicesGlTest : public GlTest {};

}  // namespace

TEST(ClusterSlicePalette, NeighbouringAndAllSlicesAreDistinct) {
    // The GL test below recovers a slice from its 8-bit colour by the nearest palette entry: that
    // needs every pair of colours far apart compared with the 8-bit rounding.
    for (int a = 0; a < kClusterSlices; ++a)
        for (int b = a + 1; b < kClusterSlices; ++b)
            EXPECT_GT(glm::length(clusterSliceColor(a) - clusterSliceColor(b)), 0.05f) << a << " vs " << b;
}

TEST_F(ClusterSlicesGlTest, EachSurfacePixelShowsTheCpuSliceOfItsDepth) {
    SceneData scene = makeDefaultScene();
    std::unique_ptr<Renderer> r = makeRenderer(kW, kH);
    ASSERT_FALSE(r->setScene(scene));
    Camera cam;
    cam.position = {0.0f, 3.0f, 14.0f};  // low over the courtyard: surfaces from near to far
    cam.lookAt({0.0f, 1.0f, -6.0f});
    PipelineSettings s;
    s.view = DebugView::ClusterSlices;
    s.lightCubes = false;
    FrameStats const st = r->render({cam, scene.lights, s, true});
    ASSERT_EQ(st.glErrors, 0u);
    FloatImage const image = r->readAttachment(Attachment::Final);  // rows top to bottom
    FloatImage const depth = r->readAttachment(Attachment::Depth);
    float const n = cam.nearPlane, f = cam.farPlane;

    int surface = 0, matched = 0, boundary = 0, background = 0;
    std::set<int> seen;
    for (int row = 0; row < kH; ++row) {
        if (kH - 1 - row < 24) continue;  // the legend's rows (6..22 from the bottom, with its frame)
        for (int x = 0; x < kW; ++x) {
            glm::vec3 const got = rgbAt(image, x, row);
            float const d = depth.at(x, row, 0);
            if (!(d < 1.0f)) {
                EXPECT_LT(glm::length(got), kColourTolerance) << "background at " << x << "," << row;
                ++background;
                continue;
            }
            ++surface;
            float const z = linearDepth(d, n, f);
            int const cpu = clusterSlice(z, n, f);
            seen.insert(cpu);
            int const shown = nearestSlice(got);
            if (shown == cpu) {
                glm::vec3 const e = glm::abs(got - clusterSliceColor(cpu));
                EXPECT_LE(std::max({e.x, e.y, e.z}), kColourTolerance) << "pixel " << x << "," << row;
                ++matched;
                continue;
            }
            // GPU and CPU logarithms may differ in the last bits: a depth within 1e-4 of a slice
            // boundary (in slice units) may land on either side, never further.
            float const sCont = std::log(z / n) / std::log(f / n) * float(kClusterSlices);
            EXPECT_LT(std::abs(sCont - std::round(sCont)), 1e-4f)
                << "pixel " << x << "," << row << " shows slice " << shown << ", the CPU says " << cpu;
            EXPECT_EQ(std::abs(shown - cpu), 1);
            ++boundary;
        }
    }
    EXPECT_GT(surface, kW * kH / 2);
    EXPECT_GE(matched, surface - surface / 1000);
    EXPECT_GE(seen.size(), 6u) << "the camera should see surfaces over several slices";

    // Legend: swatch k spans texels 8 + 12k .. 8 + 12k + 11 (kSliceSwatchTexels), rows 6..21 from the bottom.
    ASSERT_EQ(kSliceSwatchTexels * kClusterSlices, 288);  // fits the 320-wide frame: full swatches
    for (int k = 0; k < kClusterSlices; ++k) {
        glm::vec3 const e = glm::abs(rgbAt(image, 8 + kSliceSwatchTexels * k + 6, kH - 1 - 14) - clusterSliceColor(k));
        EXPECT_LE(std::max({e.x, e.y, e.z}), kColourTolerance) << "legend swatch " << k;
    }
}
