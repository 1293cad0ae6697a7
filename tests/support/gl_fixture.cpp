// Headless context set-up for GL tests.
#include "gl_fixture.h"

#include "gl/debug.h"

namespace gbl::test {

namespace {
std::unique_ptr<HeadlessContext> gContext;
GlCaps gCaps;
std::string gError;
}  // namespace

void GlTest::SetUpTestSuite() {
    if (gContext) return;
    gContext = HeadlessContext::create(&gError);
    if (gContext) {
        gCaps = detectGlCaps();
        installGlDebug(gCaps);
    }
}

void GlTest::SetUp() {
    // A missing context is a failure, not a skip: every machine this runs on has EGL or a display.
    ASSERT_TRUE(gContext) << "no headless GL context: " << gError;
    collectGlErrors();  // start each test from a clean error state
}

void GlTest::TearDown() {
    if (gContext) {
        EXPECT_EQ(collectGlErrors(), 0u) << "the GL reported errors during this test (see stderr)";
    }
}

GlCaps const& GlTest::caps() { return gCaps; }

std::unique_ptr<Renderer> GlTest::makeRenderer(int width, int height) {
    return std::make_unique<Renderer>(gCaps, width, height);
}

}  // namespace gbl::test
