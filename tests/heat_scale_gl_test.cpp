// The count heat maps on one colour scale (issue 13): volume coverage (heat map in volumes mode),
// lights per tile (the tile view) and lights per cluster (heat map in clustered mode) paint each
// pixel in the CPU bin colour of its count (core/heat_scale.h), the same count gets the same
// colour in all three, and the legend shows the eight bins' colours in order.
#include "core/heat_scale.h"
#include "gl_fixture.h"
#include "test_scenes.h"

#include <string>

using namespace gbl;
using gbl::test::GlTest;

namespace {

constexpr int kW = 320, kH = 180;  // wide enough for full 32-texel legend swatches (8 x 32 + 16)
// The display target is RGBA8: a colour comes back within half a step of 1/255 of the float the
// shader wrote, and GPU and CPU may round the dimming product differently in the last float bit.
constexpr float kColourTolerance = 1.5f / 255.0f;
// A pixel looking at the floor near the origin, under every light, off the tile grid lines
// (x % 16, y % 16 != 0) and above the legend; GL row 60 from the bottom.
constexpr int kProbeX = 164, kProbeGlY = 100;

glm::vec3 rgbAt(FloatImage const& img, int x, int glY) {
    int const row = img.height - 1 - glY;
    return {img.at(x, row, 0), img.at(x, row, 1), img.at(x, row, 2)};
}

float maxDiff(glm::vec3 a, glm::vec3 b) {
    glm::vec3 const d = glm::abs(a - b);
    return std::max({d.x, d.y, d.z});
}

std::string text(glm::vec3 c) {
    return "(" + std::to_string(c.r * 255.0f) + ", " + std::to_string(c.g * 255.0f) + ", " +
           std::to_string(c.b * 255.0f) + ")";
}

// `n` point lights 1 unit over the floor, within 0.5 of the origin: radius about 5.1 each
// (default attenuation), so every one reaches and lights the floor around the origin, and the
// camera 11 units away is outside every volume.
std::vector<PointLight> lightsOverOrigin(int n) {
    std::vector<PointLight> out;
    for (int i = 0; i < n; ++i) {
        PointLight l;
        float const a = 6.2831853f * float(i) / float(std::max(n, 1));
        l.position = {0.5f * std::cos(a), 1.0f, 0.5f * std::sin(a)};
        l.intensity = 1.0f;
        out.push_back(l);
    }
    return out;
}

struct CountView {
    char const* name;
    LightingMode mode;
    DebugView view;
};
constexpr CountView kViews[] = {{"volumes per pixel", LightingMode::Volumes, DebugView::Heatmap},
                                {"lights per tile", LightingMode::Tiled, DebugView::TileLights},
                                {"lights per cluster", LightingMode::Clustered, DebugView::Heatmap}};

class HeatScaleGlTest : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        renderer_ = makeRenderer(kW, kH);
        ASSERT_FALSE(renderer_->setScene(test::floorScene()));
        camera_.position = {0.0f, 9.0f, 6.0f};
        camera_.lookAt({0.0f, 0.0f, 0.0f});
    }
    void TearDown() override {
        renderer_.reset();
        GlTest::TearDown();
    }
    // Why the view cannot run here (its mode needs compute shaders), empty when it can.
    std::string unavailable(CountView const& v) {
        if (auto why = renderer_->modeUnavailable(v.mode)) return *why;
        return {};
    }
    struct Shown {
        FloatImage image;     // the displayed view, RGBA, rows top to bottom
        FloatImage coverage;  // the counts it was drawn from: x evaluated, y lit
    };
    Shown show(CountView const& v, std::vector<PointLight> const& lights) {
        PipelineSettings s;
        s.mode = v.mode;
        s.view = v.view;
        s.lightCubes = false;
        FrameStats const st = renderer_->render({camera_, lights, s, true});
        EXPECT_EQ(st.glErrors, 0u);
        EXPECT_TRUE(st.fallbackReason.empty()) << st.fallbackReason;
        return {renderer_->readAttachment(Attachment::Final), renderer_->readAttachment(Attachment::Coverage)};
    }

    std::unique_ptr<Renderer> renderer_;
    Camera camera_;
};

}  // namespace

TEST_F(HeatScaleGlTest, KnownCountsShowTheirBinColourInEveryCountView) {
    // One count per bin and both ends of some: 0, 1, 2-3, 4-7, 8-15, 16-31, 32-63, 64+.
    for (int n : {0, 1, 2, 3, 4, 7, 8, 16, 31, 32, 64, 70}) {
        std::vector<PointLight> const lights = lightsOverOrigin(n);
        glm::vec3 const expected = heatBinColor(heatBin(float(n)));
        std::vector<glm::vec3> shown;
        for (CountView const& v : kViews) {
            if (std::string const why = unavailable(v); !why.empty()) {
                std::printf("%s not checked: %s\n", v.name, why.c_str());
                continue;
            }
            Shown const s = show(v, lights);
            float const evaluated = s.coverage.at(kProbeX, kH - 1 - kProbeGlY, 0);
            float const lit = s.coverage.at(kProbeX, kH - 1 - kProbeGlY, 1);
            // Every light's volume, the tile's and the cluster's list hold all n lights here, and
            // all of them light the floor: the full (undimmed) colour of n's bin.
            EXPECT_EQ(evaluated, float(n)) << v.name;
            EXPECT_EQ(lit, float(n)) << v.name;
            glm::vec3 const got = rgbAt(s.image, kProbeX, kProbeGlY);
            EXPECT_LE(maxDiff(got, expected), kColourTolerance)
                << v.name << ", " << n << " lights: shows " << text(got) << ", bin " << heatBin(float(n)) << " is "
                << text(expected);
            shown.push_back(got);
        }
        for (std::size_t i = 1; i < shown.size(); ++i)
            EXPECT_LE(maxDiff(shown[i], shown[0]), kColourTolerance) << n << " lights: view " << i << " vs view 0";
    }
}

TEST_F(HeatScaleGlTest, EveryPixelShowsTheCpuColourOfItsCount) {
    // Lights spread over the floor (radii about 5.1, 3 units apart): counts from 0 to several per
    // pixel, pixels where some evaluated lights do not light the surface (dimmed in the heat
    // map), and tile/cluster lists longer than a pixel's share.
    std::vector<PointLight> lights;
    for (int i = 0; i < 7; ++i)
        for (int j = 0; j < 7; ++j) {
            PointLight l;
            l.position = {-9.0f + 3.0f * float(i), 0.4f + 0.3f * float((i + j) % 4), -9.0f + 3.0f * float(j)};
            lights.push_back(l);
        }
    for (CountView const& v : kViews) {
        if (std::string const why = unavailable(v); !why.empty()) {
            std::printf("%s not checked: %s\n", v.name, why.c_str());
            continue;
        }
        Shown const s = show(v, lights);
        int checked = 0, bins = 0, dimmed = 0;
        bool seen[kHeatBins] = {};
        for (int glY = 24; glY < kH; ++glY)  // above the legend (rows 5..22 with its frame)
            for (int x = 0; x < kW; ++x) {
                float const evaluated = s.coverage.at(x, kH - 1 - glY, 0);
                float const lit = s.coverage.at(x, kH - 1 - glY, 1);
                glm::vec3 expected;
                if (v.view == DebugView::Heatmap) {
                    expected = heatMapColor(evaluated, lit);
                    dimmed += lit < evaluated;
                } else {
                    // The tile view draws the 16x16 grid at half brightness.
                    expected = heatBinColor(heatBin(evaluated)) * (x % 16 == 0 || glY % 16 == 0 ? 0.5f : 1.0f);
                }
                glm::vec3 const got = rgbAt(s.image, x, glY);
                ASSERT_LE(maxDiff(got, expected), kColourTolerance)
                    << v.name << " pixel " << x << "," << glY << " count " << evaluated << " lit " << lit << ": shows "
                    << text(got) << ", expected " << text(expected);
                ++checked;
                bins += !seen[heatBin(evaluated)];
                seen[heatBin(evaluated)] = true;
            }
        EXPECT_EQ(checked, kW * (kH - 24));
        EXPECT_GE(bins, 3) << v.name << ": the scene should give counts in several bins";
        if (v.view == DebugView::Heatmap) {
            EXPECT_GT(dimmed, 0) << v.name << ": some evaluated lights miss";
        }
    }
}

TEST_F(HeatScaleGlTest, LegendShowsTheEightBinsInOrderWithEqualWidths) {
    std::vector<PointLight> const lights = lightsOverOrigin(3);
    for (CountView const& v : kViews) {
        if (std::string const why = unavailable(v); !why.empty()) {
            std::printf("%s not checked: %s\n", v.name, why.c_str());
            continue;
        }
        Shown const s = show(v, lights);
        // Swatch k spans texels 8 + 32k .. 8 + 32k + 31, rows 6..21 from the bottom, framed in white.
        for (int k = 0; k < kHeatBins; ++k)
            for (int x = 8 + kHeatSwatchTexels * k; x < 8 + kHeatSwatchTexels * (k + 1); ++x) {
                glm::vec3 const upper = rgbAt(s.image, x, 18), lower = rgbAt(s.image, x, 9);
                EXPECT_LE(maxDiff(upper, heatBinColor(k)), kColourTolerance) << v.name << " swatch " << k << " x " << x;
                // The heat map's lower half: the colour where none of the evaluated lights lit.
                float const dim = v.view == DebugView::Heatmap ? kHeatWastedDim : 1.0f;
                EXPECT_LE(maxDiff(lower, heatBinColor(k) * dim), kColourTolerance)
                    << v.name << " swatch " << k << " x " << x << " (lower half)";
            }
        EXPECT_LE(maxDiff(rgbAt(s.image, 7, 14), glm::vec3(1.0f)), kColourTolerance) << "left frame";
        EXPECT_LE(maxDiff(rgbAt(s.image, 8 + kHeatSwatchTexels * kHeatBins, 14), glm::vec3(1.0f)), kColourTolerance)
            << "right frame";
    }
}
