// A headless GL context shared by every test of a GL test binary, with an error check after each test.
#pragma once

#include "core/camera.h"
#include "gl/caps.h"
#include "gl/headless_context.h"
#include "renderer.h"
#include "scene/scene_data.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace gbl::test {

class GlTest : public ::testing::Test {
protected:
    static void SetUpTestSuite();
    // Ends the context (eglTerminate) before the process exits. Mesa writes its shader cache from a
    // thread; a context still alive at exit leaves that thread's pending writes to Mesa's exit
    // handler, which drops them (a leak LeakSanitizer reports when two tests fill the cache at once).
    static void TearDownTestSuite();
    // Records the process's GL error count (gl/debug.h), which only ever grows.
    void SetUp() override;
    // Fails the test when the GL reported any error while it ran (expectNoGlErrors()), or the
    // shader checks an out-of-range access (GBL_SHADER_CHECKS=1, set for every GL test).
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
    std::uint64_t checksAtSetUp_ = 0;  // shaderCheckFailureCount() at SetUp (gl/shader_checks.h)
};

// The generated default scene seen from above its courtyard, higher than any light's volume
// reaches (lights are at most 3 units up with radii up to 7.5), so every cull mode holds and every
// light's highlight is in view: the set-up the tests comparing lighting modes share. The size is
// the test's; `needsCompute` skips, with the reason, where compute shaders are missing.
class CourtyardGlTest : public GlTest {
protected:
    CourtyardGlTest(int width, int height, bool needsCompute = false)
        : width_(width), height_(height), needsCompute_(needsCompute) {}
    void SetUp() override;
    void TearDown() override;

    SceneData scene_;
    std::vector<PointLight> lights_;  // the scene's lights, which tests may change
    Camera camera_;
    std::unique_ptr<Renderer> renderer_;

private:
    int width_;
    int height_;
    bool needsCompute_;
};

}  // namespace gbl::test
