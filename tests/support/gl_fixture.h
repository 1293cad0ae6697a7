// A headless GL context shared by every test of a GL test binary, with an error check after each test.
#pragma once

#include "gl/caps.h"
#include "gl/headless_context.h"
#include "renderer.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>

namespace gbl::test {

class GlTest : public ::testing::Test {
protected:
    static void SetUpTestSuite();
    // Records the process's GL error count (gl/debug.h), which only ever grows.
    void SetUp() override;
    // Fails the test when the GL reported any error while it ran (expectNoGlErrors()).
    void TearDown() override;

    // GL errors reported since SetUp (or the last acceptGlErrors()), whoever raised them.
    std::uint64_t glErrorsSinceSetUp() const;
    // The check TearDown runs: the GL error flag is clear and the count has not grown.
    void expectNoGlErrors() const;
    // For tests that raise errors on purpose: counts from here on.
    void acceptGlErrors();

    static GlCaps const& caps();
    std::unique_ptr<Renderer> makeRenderer(int width, int height);

private:
    std::uint64_t errorsAtSetUp_ = 0;
};

}  // namespace gbl::test
