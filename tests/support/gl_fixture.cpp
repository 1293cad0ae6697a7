// Headless context set-up for GL tests.
#include "gl_fixture.h"

#include "gl/debug.h"
#include "gl/shader_checks.h"
#include "scene/default_scene.h"

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

void GlTest::TearDownTestSuite() {
    gContext.reset();
}

void GlTest::SetUp() {
    // A missing context is a failure, not a skip: every machine this runs on has EGL or a display.
    ASSERT_TRUE(gContext) << "no headless GL context: " << gError;
    acceptGlErrors();
}

void GlTest::TearDown() {
    if (!gContext) return;
    expectNoGlErrors();
    std::uint64_t const checks = shaderCheckFailureCount() - checksAtSetUp_;
    EXPECT_EQ(checks, 0u) << "the shader checks found out-of-range accesses during this test: "
                          << lastShaderCheckReport();
}

std::uint64_t GlTest::glErrorsSinceSetUp() const {
    return glErrorCount() - errorsAtSetUp_;
}

void GlTest::expectNoGlErrors() const {
    // The flag directly (as MAGNUM_VERIFY_NO_GL_ERROR does), then the count, which also holds
    // errors that code under test read off the flag or that the debug callback received.
    GLenum const flag = glGetError();
    std::uint64_t const counted = glErrorsSinceSetUp();
    EXPECT_TRUE(flag == GL_NO_ERROR && counted == 0)
        << "the GL reported errors during this test (see stderr): error flag 0x" << std::hex << flag << std::dec << ", "
        << counted << " counted";
}

void GlTest::acceptGlErrors() {
    errorsAtSetUp_ = glErrorCount();
    checksAtSetUp_ = shaderCheckFailureCount();
}

GlCaps const& GlTest::caps() {
    return gCaps;
}

std::unique_ptr<Renderer> GlTest::makeRenderer(int width, int height) {
    return std::make_unique<Renderer>(gCaps, width, height);
}

void CourtyardGlTest::SetUp() {
    GlTest::SetUp();
    if (needsCompute_ && !caps().computeShaders) GTEST_SKIP() << caps().tiledUnavailableReason();
    scene_ = makeDefaultScene();
    lights_ = scene_.lights;
    camera_.position = {0.0f, 11.5f, 10.0f};
    camera_.lookAt({0.0f, 0.0f, -2.0f});
    renderer_ = makeRenderer(width_, height_);
    ASSERT_FALSE(renderer_->setScene(scene_));
}

void CourtyardGlTest::TearDown() {
    renderer_.reset();
    GlTest::TearDown();
}

}  // namespace gbl::test
