// The GL error check itself: an error raised inside Renderer::render() reaches the fixture's
// teardown check even though render() reads the error flag and reports its own count.
#include "gl_fixture.h"
#include "renderer_test_access.h"
#include "test_scenes.h"

#include <gtest/gtest-spi.h>

using namespace gbl;
using gbl::test::GlTest;

namespace {

Camera floorCamera() {
    Camera c;
    c.position = {0.0f, 5.0f, 5.0f};
    c.lookAt({0.0f, 0.0f, 0.0f});
    return c;
}

PipelineSettings quadSettings() {
    PipelineSettings s;
    s.mode = LightingMode::Quad;
    return s;
}

}  // namespace

class GlErrorCheckGlTest : public GlTest {};

TEST_F(GlErrorCheckGlTest, CleanFrameLeavesTheCountAlone) {
    auto r = makeRenderer(32, 32);
    ASSERT_FALSE(r->setScene(test::floorScene()));
    FrameStats const s = r->render({floorCamera(), {}, quadSettings()});
    EXPECT_EQ(s.glErrors, 0u);
    EXPECT_EQ(glErrorsSinceSetUp(), 0u);
}

TEST_F(GlErrorCheckGlTest, ErrorInsideRenderReachesTheFixture) {
    auto r = makeRenderer(32, 32);
    ASSERT_FALSE(r->setScene(test::floorScene()));
    // GL_INVALID_ENUM: 0xFFFF names no capability.
    RendererTestAccess::setFrameHook(*r, [] { glEnable(0xFFFF); });
    FrameStats const s = r->render({floorCamera(), {}, quadSettings()});
    RendererTestAccess::setFrameHook(*r, {});
    EXPECT_EQ(s.glErrors, 1u) << "the frame reports the error it raised";
    EXPECT_EQ(r->glErrorCount(), 1u);
    // render() has read the error flag; the count still holds the error for everyone.
    EXPECT_EQ(glErrorsSinceSetUp(), 1u);
    // The teardown check fails on it (this is what every GL test runs after its body).
    EXPECT_NONFATAL_FAILURE(expectNoGlErrors(), "the GL reported errors during this test");
    // A later clean frame does not hide it: the count never goes back.
    EXPECT_EQ(r->render({floorCamera(), {}, quadSettings()}).glErrors, 0u);
    EXPECT_EQ(glErrorsSinceSetUp(), 1u);
    acceptGlErrors();  // raised on purpose; the teardown of this test must pass
}

TEST_F(GlErrorCheckGlTest, ErrorLeftOnTheFlagIsCaughtDirectly) {
    glEnable(0xFFFF);  // raised outside any renderer, never read by anyone
    EXPECT_NONFATAL_FAILURE(expectNoGlErrors(), "error flag 0x500");  // GL_INVALID_ENUM
    acceptGlErrors();
}
