// The headless context: the backend GBL_HEADLESS asks for is the one in use, and its context renders.
#include "gl/caps.h"
#include "gl/debug.h"
#include "gl/framebuffer.h"
#include "gl/headless_context.h"
#include "gl/texture.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <iostream>
#include <string>

using namespace gbl;

namespace {

// What create() must pick: the backend named by GBL_HEADLESS, else EGL where the build has it.
std::string expectedBackend() {
    char const* env = std::getenv("GBL_HEADLESS");
    if (env && *env) return env;
    return HeadlessContext::hasEgl() ? "egl" : "glfw";
}

// Sets an environment variable for one scope and restores the old value after it.
class ScopedEnv {
public:
    ScopedEnv(char const* name, char const* value) : name_(name) {
        if (char const* old = std::getenv(name)) old_ = old;
        had_ = std::getenv(name) != nullptr;
        setenv(name, value, 1);
    }
    ~ScopedEnv() {
        if (had_)
            setenv(name_, old_.c_str(), 1);
        else
            unsetenv(name_);
    }

private:
    char const* name_;
    std::string old_;
    bool had_ = false;
};

}  // namespace

TEST(HeadlessContext, UsesTheBackendAskedFor) {
    std::string error;
    auto ctx = HeadlessContext::create(&error);
    ASSERT_TRUE(ctx) << error;
    std::string const expected = expectedBackend();
    EXPECT_EQ(backendName(ctx->backend()), expected);
    // Independent of what create() says: GLFW knows whether the current context is one of its windows.
    if (expected == "glfw")
        EXPECT_NE(glfwGetCurrentContext(), nullptr) << "the backend says glfw, but no GLFW context is current";
    else
        EXPECT_EQ(glfwGetCurrentContext(), nullptr) << "the backend says egl, but a GLFW window's context is current";

    GlCaps const caps = detectGlCaps();
    EXPECT_TRUE(caps.atLeast(3, 3)) << "got OpenGL " << caps.version;
    GLint profile = 0;
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT) << "not a core-profile context: " << caps.version;
    std::cout << "backend " << backendName(ctx->backend()) << ": " << caps.renderer << ", " << caps.version << "\n";
}

TEST(HeadlessContext, ClearsAndReadsBackPixels) {
    std::string error;
    auto ctx = HeadlessContext::create(&error);
    ASSERT_TRUE(ctx) << error;
    EXPECT_EQ(collectGlErrors(), 0u);
    {
        auto color = gl::Texture::create2D(GL_RGBA8, 4, 4, "headless test colour");
        auto fb = gl::Framebuffer::create({&color}, nullptr, "headless test target");
        ASSERT_FALSE(fb.error()) << *fb.error();
        glBindFramebuffer(GL_FRAMEBUFFER, fb.id());
        glViewport(0, 0, 4, 4);
        glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        std::array<unsigned char, 4> px{};
        glReadPixels(2, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
        // UNORM8 stores round(c * 255): 63.75 -> 64, 127.5 -> 128 (or 127: round-half is the driver's), 191.25 -> 191.
        EXPECT_EQ(px[0], 64);
        EXPECT_NEAR(px[1], 127.5, 0.5);
        EXPECT_EQ(px[2], 191);
        EXPECT_EQ(px[3], 255);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    EXPECT_EQ(collectGlErrors(), 0u);
}

TEST(HeadlessContext, RefusesAnUnknownBackendName) {
    ScopedEnv env("GBL_HEADLESS", "vulkan");
    std::string error;
    EXPECT_FALSE(HeadlessContext::create(&error));
    EXPECT_NE(error.find("GBL_HEADLESS=vulkan"), std::string::npos) << error;
    EXPECT_NE(error.find("egl or glfw"), std::string::npos) << error;
}

TEST(HeadlessContext, GlfwWithoutADisplaySaysHowToGetOne) {
    // Only an X11 GLFW needs DISPLAY; with the display removed, the sentence must say what to do.
    ScopedEnv backend("GBL_HEADLESS", "glfw");
    ScopedEnv display("DISPLAY", "");
    ScopedEnv wayland("WAYLAND_DISPLAY", "");
    std::string error;
    auto ctx = HeadlessContext::create(&error);
    if (ctx) GTEST_SKIP() << "this GLFW opened a window without DISPLAY (not X11)";
    EXPECT_NE(error.find("no display for a hidden GLFW window"), std::string::npos) << error;
    EXPECT_NE(error.find("xvfb-run"), std::string::npos) << error;
}
