// The viewport's lit-frame pin on real frames: an unchanged frame diffs to exactly 0, a brighter
// light to a positive difference, and the heat map texture is the diff's size.
#include "editor/viewer_tools_service.h"
#include "gl_fixture.h"
#include "scene/default_scene.h"

#include <epoxy/gl.h>

using namespace gbl;
using gbl::test::GlTest;

namespace {

constexpr int kW = 96, kH = 64;

class LitPinGlTest : public GlTest {};

TEST_F(LitPinGlTest, PinThenDiffOnRealFrames) {
    SceneData scene = makeDefaultScene();
    Camera camera;
    camera.position = {0.0f, 11.5f, 10.0f};
    camera.lookAt({0.0f, 0.0f, -2.0f});
    auto renderer = makeRenderer(kW, kH);
    ASSERT_FALSE(renderer->setScene(scene));
    PipelineSettings const settings;
    renderer->render({camera, scene.lights, settings, true});

    ui::LitPin pin;
    ui::ViewerToolsGpu gpu;
    EXPECT_EQ(ui::serviceLitPin(pin, *renderer, 0, gpu), 0u);  // nothing asked: no read-back
    EXPECT_EQ(pin.frame, -1);
    pin.pinRequested = true;
    EXPECT_EQ(ui::serviceLitPin(pin, *renderer, 1, gpu), 0u);  // pinned, diff not shown yet
    ASSERT_TRUE(pin.pinned);
    EXPECT_EQ(pin.pinned->width, kW);
    EXPECT_GT(pin.stats.shown.max, 0.0f);

    // The same frame again: exactly equal, so the diff is 0 everywhere.
    renderer->render({camera, scene.lights, settings, true});
    pin.showDiff = true;
    unsigned const same = ui::serviceLitPin(pin, *renderer, 2, gpu);
    ASSERT_NE(same, 0u);
    ASSERT_TRUE(pin.diff.comparable);
    EXPECT_EQ(pin.diff.max, 0.0f);
    EXPECT_EQ(pin.diff.overThreshold, 0);
    EXPECT_EQ(pin.diff.pixels, long(kW) * kH);
    EXPECT_EQ(gpu.litDiff.width(), kW);
    EXPECT_EQ(gpu.litDiff.height(), kH);

    // Every light twice as bright: lit pixels change, by at most the brighter frame's own value.
    for (PointLight& l : scene.lights) l.intensity *= 2.0f;
    renderer->render({camera, scene.lights, settings, true});
    EXPECT_EQ(ui::serviceLitPin(pin, *renderer, 2 + ui::kViewerDataInterval, gpu), same);
    EXPECT_GT(pin.diff.max, 0.0f);
    EXPECT_GT(pin.diff.overThreshold, 0);
    EXPECT_LE(pin.diff.max, pin.stats.shown.max);

    // A threshold applies at once, from the read-back already held (no frame is due for one).
    long const over = pin.diff.overThreshold;
    long const readAt = pin.frame;
    pin.diffThreshold = pin.diff.max * 0.5f;
    EXPECT_EQ(ui::serviceLitPin(pin, *renderer, readAt + 1, gpu), same);
    EXPECT_EQ(pin.frame, readAt);
    EXPECT_LT(pin.diff.overThreshold, over);
    EXPECT_GT(pin.diff.overThreshold, 0);  // the brightest change is still over half of itself
    pin.diffThreshold = pin.diff.max * 2.0f;
    ui::serviceLitPin(pin, *renderer, readAt + 2, gpu);
    EXPECT_EQ(pin.diff.overThreshold, 0);
}

}  // namespace
