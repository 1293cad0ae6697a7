// Each view has a program of its own (view.frag built with VIEW_ONLY, RendererImpl::viewProgram):
// every view draws exactly the picture the one program switching on uView draws, in each
// G-buffer layout; a view's program is built once, on first use; a variant that fails to build
// falls back to the general program.
#include "gl/shader_library.h"
#include "gl_fixture.h"
#include "renderer_test_access.h"
#include "scene/default_scene.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

using namespace gbl;
using gbl::test::GlTest;

namespace {

constexpr int kW = 96, kH = 54;

// The frame a view needs: the tile and slice views show tiled and clustered lists, the split
// light views the split accumulation's targets.
PipelineSettings frameFor(DebugView view, GBufferLayout layout) {
    PipelineSettings s;
    s.layout = layout;
    s.lightCubes = false;
    if (view == DebugView::TileLights) s.mode = LightingMode::Tiled;
    if (view == DebugView::ClusterSlices) s.mode = LightingMode::Clustered;
    if (view == DebugView::DiffuseLight || view == DebugView::SpecularLight) s.accumulation = LightAccumulation::Split;
    return s;
}

double largestDifference(FloatImage const& a, FloatImage const& b) {
    double d = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) d = std::max(d, double(std::abs(a.pixels[i] - b.pixels[i])));
    return d;
}

class ViewProgramsGlTest : public GlTest {};

TEST_F(ViewProgramsGlTest, EveryViewsOwnProgramDrawsWhatTheGeneralOneDraws) {
    SceneData const scene = makeDefaultScene();
    auto renderer = makeRenderer(kW, kH);
    ASSERT_FALSE(renderer->setScene(scene));
    Camera const camera = scene.camera.value_or(Camera{});
    int pictures = 0, compared = 0;
    for (GBufferLayout layout : {GBufferLayout::Classic, GBufferLayout::Packed}) {
        for (std::size_t v = 0; v < kDebugViewNames.size(); ++v) {
            DebugView const view = DebugView(v);
            SCOPED_TRACE(std::string(kDebugViewNames[v]) + ", " +
                         std::string(kGBufferLayoutNames[std::size_t(layout)]));
            PipelineSettings const s = frameFor(view, layout);
            if (renderer->modeUnavailable(s.mode)) continue;
            FrameInput const frame{camera, scene.lights, s};
            renderer->render(frame);
            ViewParams params;
            params.view = view;
            params.rangeMax = 4.0f;
            ViewTarget own, general;
            RendererTestAccess::setViewVariants(*renderer, true);
            renderer->drawView(params, frame, own);
            RendererTestAccess::setViewVariants(*renderer, false);
            renderer->drawView(params, frame, general);
            RendererTestAccess::setViewVariants(*renderer, true);
            FloatImage const a = renderer->readViewTarget(own), b = renderer->readViewTarget(general);
            ASSERT_EQ(a.pixels.size(), b.pixels.size());
            EXPECT_EQ(largestDifference(a, b), 0.0);
            // The pictures compared are pictures: in most views the scene fills most of the frame
            // (the default scene emits no light, so its emission and the attachments that hold
            // it are dark).
            std::size_t lit = 0;
            for (float x : a.pixels) lit += x > 0.0f;
            pictures += lit > a.pixels.size() / 4;
            ++compared;
        }
    }
    EXPECT_EQ(compared, 2 * int(kDebugViewNames.size()));
    EXPECT_GE(pictures, compared - 6);
    EXPECT_EQ(renderer->glErrorCount(), 0u);
}

TEST_F(ViewProgramsGlTest, AViewsProgramIsBuiltOnceOnFirstUse) {
    SceneData const scene = makeDefaultScene();
    auto renderer = makeRenderer(kW, kH);
    ASSERT_FALSE(renderer->setScene(scene));
    PipelineSettings s;
    FrameInput const frame{scene.camera.value_or(Camera{}), scene.lights, s};
    renderer->render(frame);
    std::size_t const afterFirst = RendererTestAccess::shaderBuilds(*renderer);
    renderer->render(frame);
    EXPECT_EQ(RendererTestAccess::shaderBuilds(*renderer), afterFirst) << "the final view's program is kept";
    ViewParams normals;
    normals.view = DebugView::Normal;
    ViewTarget target;
    renderer->drawView(normals, frame, target);
    EXPECT_EQ(RendererTestAccess::shaderBuilds(*renderer), afterFirst + 1) << "the normal view's, on first use";
    renderer->drawView(normals, frame, target);
    renderer->render(frame);
    EXPECT_EQ(RendererTestAccess::shaderBuilds(*renderer), afterFirst + 1);
}

TEST_F(ViewProgramsGlTest, AVariantThatFailsToBuildFallsBackToTheProgram) {
    ShaderLibrary shaders{std::filesystem::path()};
    ASSERT_TRUE(shaders.add(ProgramId::View, nullptr));
    std::size_t const builds = shaders.buildCount();
    // Not a view: `switch (no_such_view)` does not compile.
    gl::Program const& broken = shaders.variant(ProgramId::View, "VIEW_ONLY no_such_view");
    EXPECT_EQ(broken.id(), shaders.get(ProgramId::View).id());
    EXPECT_EQ(shaders.buildCount(), builds);
    gl::Program const& normal = shaders.variant(ProgramId::View, "VIEW_ONLY 3");
    EXPECT_NE(normal.id(), shaders.get(ProgramId::View).id());
    EXPECT_EQ(shaders.buildCount(), builds + 1);
    EXPECT_EQ(shaders.variant(ProgramId::View, "VIEW_ONLY 3").id(), normal.id()) << "built once";
}

// Hot reload: a view.frag broken on disk leaves every view drawn by the last good general program
// (its variants cannot build, and are not tried again every frame); fixed, the views get their own
// programs back.
TEST_F(ViewProgramsGlTest, ABrokenViewShaderFallsBackUntilFixed) {
    namespace fs = std::filesystem;
    fs::path const dir = fs::temp_directory_path() / ("gbl_view_reload_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::path const file = dir / "view.frag";
    fs::copy_file(fs::path(GBL_SOURCE_DIR) / "shaders" / "view.frag", file, fs::copy_options::overwrite_existing);
    std::string const good = [&] {
        std::ifstream in(file);
        return std::string(std::istreambuf_iterator<char>(in), {});
    }();
    auto writeLater = [&](std::string const& text) {
        auto const before = fs::last_write_time(file);  // file times can be coarse
        std::ofstream(file) << text;
        fs::last_write_time(file, before + std::chrono::seconds(1));
    };
    ShaderLibrary shaders(dir);
    std::string log;
    ASSERT_TRUE(shaders.add(ProgramId::View, &log)) << log;
    GLuint const general = shaders.get(ProgramId::View).id();
    EXPECT_NE(shaders.variant(ProgramId::View, "VIEW_ONLY 3").id(), general);

    writeLater(good + "\n#error broken on purpose\n");
    auto messages = shaders.reloadChanged();
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_NE(messages[0].find("keeping the last good one"), std::string::npos) << messages[0];
    std::size_t const builds = shaders.buildCount();
    EXPECT_EQ(shaders.variant(ProgramId::View, "VIEW_ONLY 3").id(), general);
    EXPECT_EQ(shaders.variant(ProgramId::View, "VIEW_ONLY 3").id(), general);
    EXPECT_EQ(shaders.buildCount(), builds);

    writeLater(good);
    messages = shaders.reloadChanged();
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_NE(messages[0].find("reloaded"), std::string::npos) << messages[0];
    std::size_t const rebuilt = shaders.buildCount();
    EXPECT_NE(shaders.variant(ProgramId::View, "VIEW_ONLY 3").id(), shaders.get(ProgramId::View).id());
    EXPECT_EQ(shaders.buildCount(), rebuilt + 1);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    fs::remove_all(dir);
}

}  // namespace
