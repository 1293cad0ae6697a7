// Viewer tools in the view pass: the NaN and Inf overlays mark exactly the texels that hold them,
// the clipping overlay marks values outside the black/white points, and the GPU colormaps match
// the CPU tables of ui/model/colormap.cpp.
#include "gl_fixture.h"
#include "model/colormap.h"
#include "model/image_stats.h"
#include "model/viewer_state.h"
#include "test_scenes.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <utility>

using namespace gbl;
using namespace gbl::ui;
using gbl::test::GlTest;

namespace {

constexpr int kW = 40, kH = 24;

class ViewerToolsGlTest : public GlTest {
protected:
    // A floor seen from above at an angle: every pixel covers the plane, positions are finite.
    void SetUp() override {
        GlTest::SetUp();
        renderer = makeRenderer(kW, kH);
        ASSERT_FALSE(renderer->setScene(test::floorScene()));
        camera.position = {0.0f, 6.0f, 3.0f};
        camera.lookAt({0.0f, 0.0f, 0.0f});
        PipelineSettings s;
        s.lightCubes = false;
        renderer->render({camera, {}, s});
    }

    // The test hook: overwrites one channel of position texels (GL's bottom-up rows) with `value`.
    void inject(std::set<std::pair<int, int>> const& glTexels, int channel, float value) {
        FloatImage const pos = renderer->readAttachment(Attachment::Position);
        glBindTexture(GL_TEXTURE_2D, renderer->texture(Attachment::Position));
        for (auto [x, y] : glTexels) {
            float texel[4];
            for (int c = 0; c < 4; ++c) texel[c] = pos.at(x, kH - 1 - y, c);
            texel[channel] = value;
            glTexSubImage2D(GL_TEXTURE_2D, 0, x, y, 1, 1, GL_RGBA, GL_FLOAT, texel);
        }
        glBindTexture(GL_TEXTURE_2D, 0);
    }

    FloatImage view(ViewParams const& p) {
        ViewTarget target;
        renderer->drawView(p, FrameInput{camera, {}, {}}, target);
        return renderer->readViewTarget(target);
    }

    std::unique_ptr<Renderer> renderer;
    Camera camera;
};

bool isColour(FloatImage const& img, int x, int y, glm::vec3 c) {
    return img.at(x, y, 0) == c.r && img.at(x, y, 1) == c.g && img.at(x, y, 2) == c.b;
}

ViewParams positionView(unsigned overlays) {
    ViewParams p;
    p.view = DebugView::Position;
    p.channelMask = 0x7;
    p.rangeMin = -20.0f;
    p.rangeMax = 20.0f;
    p.overlays = overlays;
    return p;
}

}  // namespace

TEST_F(ViewerToolsGlTest, NaNOverlayMarksExactlyTheNaNTexels) {
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    FloatImage const before = view(positionView(0));
    // NaN in x of some texels, in z of others (a corner, an edge and the middle), and +Inf in y
    // of one more: the NaN overlay must mark the NaN texels and nothing else.
    std::set<std::pair<int, int>> const nanX{{0, 0}, {kW - 1, kH - 1}, {17, 5}}, nanZ{{3, 20}, {30, 11}};
    std::set<std::pair<int, int>> const infY{{8, 8}};
    float const nan = std::numeric_limits<float>::quiet_NaN();
    inject(nanX, 0, nan);
    inject(nanZ, 2, nan);
    inject(infY, 1, std::numeric_limits<float>::infinity());
    // The injection took: the CPU statistics of the attachment count the same texels.
    ImageStats const s = imageStats(renderer->readAttachment(Attachment::Position), 0x7);
    EXPECT_EQ(s.nanPixels, 5);
    EXPECT_EQ(s.infPixels, 1);

    FloatImage const marked = view(positionView(kOverlayNaN));
    ASSERT_EQ(marked.width, kW);
    int markedCount = 0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            int const glY = kH - 1 - y;
            bool const expected = nanX.count({x, glY}) || nanZ.count({x, glY});
            bool const magenta = isColour(marked, x, y, {1.0f, 0.0f, 1.0f});
            EXPECT_EQ(magenta, expected) << x << "," << y;
            markedCount += magenta;
            // Everywhere else the view is unchanged, bit for bit (the Inf texel included).
            if (!expected && !infY.count({x, glY})) {
                for (int c = 0; c < 3; ++c) ASSERT_EQ(marked.at(x, y, c), before.at(x, y, c)) << x << "," << y;
            }
        }
    }
    EXPECT_EQ(markedCount, 5);

    // The Inf overlay marks the Inf texel alone (green); hiding the y channel hides it.
    FloatImage const inf = view(positionView(kOverlayInf));
    int green = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) green += isColour(inf, x, y, {0.0f, 1.0f, 0.0f});
    EXPECT_EQ(green, 1);
    EXPECT_TRUE(isColour(inf, 8, kH - 1 - 8, {0.0f, 1.0f, 0.0f}));
    ViewParams noY = positionView(kOverlayInf);
    noY.channelMask = 0x5;
    EXPECT_FALSE(isColour(view(noY), 8, kH - 1 - 8, {0.0f, 1.0f, 0.0f}));
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ViewerToolsGlTest, ClipOverlayMarksValuesOutsideTheBlackAndWhitePoints) {
    // Position x alone with the points at -0.5 and 0.5: texels with x < -0.5 are blue, > 0.5 red.
    FloatImage const pos = renderer->readAttachment(Attachment::Position);
    ViewParams p = positionView(kOverlayClip);
    p.channelMask = 0x1;
    p.rangeMin = -0.5f;
    p.rangeMax = 0.5f;
    FloatImage const img = view(p);
    int below = 0, above = 0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            float const v = pos.at(x, y, 0);
            EXPECT_EQ(isColour(img, x, y, {0.0f, 0.0f, 1.0f}), v < -0.5f) << x << "," << y;
            EXPECT_EQ(isColour(img, x, y, {1.0f, 0.0f, 0.0f}), v > 0.5f) << x << "," << y;
            below += v < -0.5f;
            above += v > 0.5f;
        }
    }
    // The CPU clipping counts of the same points agree, and the view has texels of each kind.
    ClipCounts const c = clipCounts(pos, 0x1, -0.5f, 0.5f);
    EXPECT_EQ(c.below, below);
    EXPECT_EQ(c.above, above);
    EXPECT_GT(below, 0);
    EXPECT_GT(above, 0);
    EXPECT_GT(c.inside, 0);
}

TEST_F(ViewerToolsGlTest, GpuColormapsMatchTheCpuTables) {
    // Position x remapped over the floor's span covers most of 0..1 across the image.
    FloatImage const pos = renderer->readAttachment(Attachment::Position);
    ImageStats const s = imageStats(pos, 0x1);
    for (Colormap map : {Colormap::Turbo, Colormap::Viridis}) {
        ViewParams p = positionView(0);
        p.channelMask = 0x1;
        p.rangeMin = s.shown.min;
        p.rangeMax = s.shown.max;
        p.colormap = map;
        FloatImage const img = view(p);
        float worst = 0.0f;
        for (int y = 0; y < kH; ++y) {
            for (int x = 0; x < kW; ++x) {
                float const t = (pos.at(x, y, 0) - p.rangeMin) / (p.rangeMax - p.rangeMin);
                glm::vec3 const expected = colormap(map, t);
                for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(img.at(x, y, c) - expected[c]));
            }
        }
        // One 8-bit step: the view target is RGBA8 (half a step of rounding) plus float error.
        EXPECT_LE(worst, 1.0f / 255.0f) << int(map);
    }
}
