// A headless GL context shared by every test of a GL test binary, with an error check after each test.
#pragma once

#include "gl/caps.h"
#include "gl/headless_context.h"
#include "renderer.h"

#include <gtest/gtest.h>

#include <memory>

namespace gbl::test {

class GlTest : public ::testing::Test {
protected:
    static void SetUpTestSuite();
    void SetUp() override;
    // Fails the test when the GL reported any error while it ran.
    void TearDown() override;

    static GlCaps const& caps();
    std::unique_ptr<Renderer> makeRenderer(int width, int height);
};

}  // namespace gbl::test
