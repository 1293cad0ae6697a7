// Viewer export: the PNG holds what the viewer shows (channels, remap), the EXR the stored floats.
#include "editor/viewer_export.h"
#include "gl_fixture.h"
#include "image/image_io.h"
#include "run_command.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace gbl;
using namespace gbl::ui;
using gbl::test::GlTest;

namespace {

class ViewerExportGlTest : public GlTest {
protected:
    // A floor seen from above at an angle: every pixel covers the +Y-facing plane.
    void SetUp() override {
        GlTest::SetUp();
        renderer = makeRenderer(48, 32);
        ASSERT_FALSE(renderer->setScene(test::floorScene()));
        camera.position = {0.0f, 6.0f, 3.0f};
        camera.lookAt({0.0f, 0.0f, 0.0f});
        PipelineSettings s;
        s.lightCubes = false;
        renderer->render({camera, {}, s});
        dir = test::freshTempDir("viewer_export");
    }
    std::unique_ptr<Renderer> renderer;
    Camera camera;
    std::string dir;
};

ViewerState viewer(ViewerKind kind) {
    ViewerState v = GBufferPanelState::defaultViewers()[std::size_t(kind)];
    v.kind = kind;
    return v;
}

}  // namespace

TEST_F(ViewerExportGlTest, PngShowsTheIsolatedChannelAsGrey) {
    // Normal (0,1,0) shown biased: R = 0.5, G = 1.0. Isolating G gives white, R gives mid grey.
    ViewerState v = viewer(ViewerKind::Normal);
    v.normalDisplay = NormalDisplay::Biased;
    v.channelMask = 0x2;
    ASSERT_EQ(exportViewerPng(*renderer, v, camera, dir + "/g.png"), std::nullopt);
    v.channelMask = 0x1;
    ASSERT_EQ(exportViewerPng(*renderer, v, camera, dir + "/r.png"), std::nullopt);
    auto const g = readImage(dir + "/g.png"), r = readImage(dir + "/r.png");
    ASSERT_TRUE(g && r);
    ASSERT_EQ(g->width, 48);
    ASSERT_EQ(g->channels, 3);
    int const x = 24, y = 16;
    for (int c = 0; c < 3; ++c) {
        // 8-bit storage: within one step of 255 (or 127.5) on each channel.
        EXPECT_NEAR(g->at(x, y, c), 1.0f, 1.0f / 255.0f) << c;
        EXPECT_NEAR(r->at(x, y, c), 0.5f, 1.0f / 255.0f) << c;
    }
}

TEST_F(ViewerExportGlTest, PngAppliesTheRangeRemap) {
    // Position z alone, remapped from [-4, 4]: each PNG value is (z + 4) / 8 of the stored z.
    ViewerState v = viewer(ViewerKind::Position);
    v.channelMask = 0x4;  // z alone
    v.rangeMin = -4.0f;
    v.rangeMax = 4.0f;
    ASSERT_EQ(exportViewerPng(*renderer, v, camera, dir + "/z.png"), std::nullopt);
    FloatImage const pos = renderer->readAttachment(Attachment::Position);
    auto const png = readImage(dir + "/z.png");
    ASSERT_TRUE(png);
    for (int y : {2, 16, 29}) {
        float const z = pos.at(24, y, 2);
        float const expected = std::clamp((z + 4.0f) / 8.0f, 0.0f, 1.0f);
        // One 8-bit step plus the RGBA16F position's rounding.
        EXPECT_NEAR(png->at(24, y, 0), expected, 1.5f / 255.0f) << y;
    }
}

TEST_F(ViewerExportGlTest, ExrHoldsTheStoredFloats) {
    ASSERT_EQ(exportViewerExr(*renderer, ViewerKind::Normal, dir + "/n.exr"), std::nullopt);
    ASSERT_EQ(exportViewerExr(*renderer, ViewerKind::Specular, dir + "/s.exr"), std::nullopt);
    ASSERT_EQ(exportViewerExr(*renderer, ViewerKind::Depth, dir + "/d.exr"), std::nullopt);
    ASSERT_EQ(exportViewerExr(*renderer, ViewerKind::Albedo, dir + "/a.exr"), std::nullopt);
    auto const n = readImage(dir + "/n.exr"), s = readImage(dir + "/s.exr"), d = readImage(dir + "/d.exr"),
               a = readImage(dir + "/a.exr");
    ASSERT_TRUE(n && s && d && a);
    EXPECT_EQ(n->channels, 4);
    EXPECT_EQ(s->channels, 1);
    EXPECT_EQ(d->channels, 1);
    EXPECT_EQ(a->channels, 3);
    EXPECT_FLOAT_EQ(n->at(10, 10, 1), 1.0f);  // the floor's normal, exactly as stored
    EXPECT_FLOAT_EQ(n->at(10, 10, 0), 0.0f);
    // The material's specular in an 8-bit channel: the nearest 8-bit value.
    EXPECT_NEAR(s->at(10, 10, 0), test::kPlaneSpecular, 0.5f / 255.0f);
    FloatImage const depth = renderer->readAttachment(Attachment::Depth);
    EXPECT_EQ(d->at(7, 9, 0), depth.at(7, 9, 0));  // bit-exact: float EXR of float data
}

TEST_F(ViewerExportGlTest, ZeroSizedFrameIsAMessage) {
    renderer->resizeTargets(0, 0);
    auto const e = exportViewerPng(*renderer, viewer(ViewerKind::Albedo), camera, dir + "/x.png");
    ASSERT_TRUE(e);
    EXPECT_NE(e->find("0x0"), std::string::npos) << *e;
    EXPECT_TRUE(exportViewerExr(*renderer, ViewerKind::Depth, dir + "/x.exr"));
}

TEST_F(ViewerExportGlTest, UnwritablePathIsAMessage) {
    auto const e = exportViewerExr(*renderer, ViewerKind::Depth, "/proc/gbl/x.exr");
    ASSERT_TRUE(e);
    EXPECT_NE(e->find("/proc/gbl/x.exr"), std::string::npos) << *e;
}
