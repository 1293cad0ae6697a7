// Render on change: the renderer runs for the first frame and after any input changed, not on an
// idle frame; continuous rendering and measurements render every frame.
#include "model/render_inputs.h"

#include <gtest/gtest.h>

#include <functional>

using namespace gbl;
using namespace gbl::ui;

namespace {
struct Inputs {
    Camera camera;
    std::vector<PointLight> lights{PointLight{}, PointLight{}};
    PipelineSettings pipeline;
    glm::ivec2 size{640, 360};
    std::uint64_t scene = 1, shaders = 0;
    float time = 0.0f;
    bool measuring = false;
    RenderInputs make() const { return renderInputs(camera, lights, pipeline, size, scene, shaders, time, measuring); }
};
}  // namespace

TEST(RenderInputs, IdleFramesReuseTheLastImage) {
    RenderOnChange r;
    Inputs in;
    EXPECT_TRUE(needsRender(r, in.make())) << "nothing rendered yet";
    for (int i = 0; i < 40; ++i) EXPECT_FALSE(needsRender(r, in.make()));
    EXPECT_EQ(r.renders, 1);
    EXPECT_EQ(r.skipped, 40);
    EXPECT_FALSE(r.renderedLastFrame);
}

TEST(RenderInputs, EachInputOnItsOwnCausesOneRender) {
    Inputs base;
    auto const changes = std::vector<std::pair<char const*, std::function<void(Inputs&)>>>{
        {"camera position", [](Inputs& i) { i.camera.position.x += 0.01f; }},
        {"camera yaw", [](Inputs& i) { i.camera.yawDegrees += 1.0f; }},
        {"field of view", [](Inputs& i) { i.camera.fovYDegrees = 50.0f; }},
        {"far plane", [](Inputs& i) { i.camera.farPlane = 90.0f; }},
        {"light colour", [](Inputs& i) { i.lights[1].color.g = 0.5f; }},
        {"light count", [](Inputs& i) { i.lights.pop_back(); }},
        {"kq", [](Inputs& i) { i.lights[0].kq = 0.44f; }},
        {"mode", [](Inputs& i) { i.pipeline.mode = LightingMode::Volumes; }},
        {"exposure", [](Inputs& i) { i.pipeline.exposure = 2.0f; }},
        {"debug view", [](Inputs& i) { i.pipeline.view = DebugView::Heatmap; }},
        {"size", [](Inputs& i) { i.size.x = 641; }},
        {"scene", [](Inputs& i) { i.scene = 2; }},
        {"shader reload", [](Inputs& i) { i.shaders = 1; }},
        {"animation time", [](Inputs& i) { i.time = 0.016f; }},
    };
    for (auto const& [what, change] : changes) {
        RenderOnChange r;
        Inputs in = base;
        needsRender(r, in.make());
        change(in);
        EXPECT_TRUE(needsRender(r, in.make())) << what;
        EXPECT_NE(describeChange(base.make(), in.make()), "nothing") << what;
        EXPECT_FALSE(needsRender(r, in.make())) << what << ": once re-rendered, idle again";
    }
}

TEST(RenderInputs, ContinuousAndMeasuringRenderEveryFrame) {
    RenderOnChange r;
    r.continuous = true;
    Inputs in;
    for (int i = 0; i < 5; ++i) EXPECT_TRUE(needsRender(r, in.make()));
    RenderOnChange m;
    in.measuring = true;
    for (int i = 0; i < 5; ++i) EXPECT_TRUE(needsRender(m, in.make()));
    EXPECT_EQ(m.renders, 5);
}

TEST(RenderInputs, DescribeNamesWhatChanged) {
    Inputs a, b;
    b.camera.position.y = 9.0f;
    b.pipeline.mode = LightingMode::Tiled;
    EXPECT_EQ(describeChange(a.make(), b.make()), "camera, pipeline");
    EXPECT_EQ(describeChange(a.make(), a.make()), "nothing");
    EXPECT_EQ(describeChange(std::nullopt, a.make()), "first frame");
}

// The Frame window's "Stop here" and "Run whole frame" each render the frame again.
TEST(RenderInputs, AStopAfterAPassRendersAgain) {
    RenderOnChange r;
    Inputs in;
    RenderInputs whole = in.make();
    EXPECT_TRUE(needsRender(r, whole));
    RenderInputs stopped = whole;
    stopped.stopAfter = PassId::Geometry;
    EXPECT_TRUE(needsRender(r, stopped));
    EXPECT_EQ(describeChange(whole, stopped), "stop after a pass");
    EXPECT_FALSE(needsRender(r, stopped));
    EXPECT_TRUE(needsRender(r, whole));
}
