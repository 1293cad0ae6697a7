// Pass times add up: they sum to no more than the frame's wall time, and the pass made heavier is the one that grows.
#include "gl/gpu_timer.h"
#include "gl_fixture.h"
#include "renderer_test_access.h"
#include "scene/default_scene.h"
#include "test_paths.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

using namespace gbl;
using gbl::test::GlTest;

namespace {

constexpr int kW = 320, kH = 180;

double passMs(FrameStats const& s, std::string const& name) {
    for (auto const& p : s.passes)
        if (p.name == name) return p.gpuMs;
    ADD_FAILURE() << "no pass named " << name;
    return 0.0;
}

struct Timed {
    double geometry = 0.0;
    double lighting = 0.0;
};

class PassTimingGlTest : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        scene_ = makeDefaultScene();
        renderer_ = makeRenderer(kW, kH);
        ASSERT_FALSE(renderer_->setScene(scene_));
        settings_.mode = LightingMode::Quad;  // every light at every pixel: cost linear in the count
        settings_.lightCubes = false;
    }
    void TearDown() override {
        renderer_.reset();
        GlTest::TearDown();
    }
    std::vector<PointLight> lights(int n) const {
        std::vector<PointLight> out;
        for (int i = 0; i < n; ++i) out.push_back(scene_.lights[std::size_t(i) % scene_.lights.size()]);
        return out;
    }
    // Renders `frames` frames, checking each one's sum against its wall time; medians of the two passes.
    Timed measure(int lightCount, int frames = 3) {
        std::vector<PointLight> const l = lights(lightCount);
        std::vector<double> g, li;
        for (int i = 0; i < frames + 1; ++i) {
            auto const t0 = std::chrono::steady_clock::now();
            FrameStats const s = renderer_->render({camera_, l, settings_, true});
            double const wallMs =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            EXPECT_EQ(s.glErrors, 0u);
            double sum = 0.0;
            for (auto const& p : s.passes) sum += p.gpuMs;
            EXPECT_DOUBLE_EQ(sum, s.gpuFrameMs);
            // The passes are disjoint intervals inside render(): their sum cannot exceed it.
            EXPECT_LE(sum, wallMs) << lightCount << " lights, " << s.timingSource;
            if (i == 0) continue;  // warm-up: shader compilation and first-use costs
            g.push_back(passMs(s, "geometry"));
            li.push_back(passMs(s, "lighting"));
        }
        std::sort(g.begin(), g.end());
        std::sort(li.begin(), li.end());
        return {g[g.size() / 2], li[li.size() / 2]};
    }

    SceneData scene_;
    Camera camera_;
    PipelineSettings settings_;
    std::unique_ptr<Renderer> renderer_;
};

TEST(TimingMethod, SoftwareRasterisersAreTimedOnTheCpu) {
    EXPECT_EQ(chooseTimingMethod("llvmpipe (LLVM 15.0.6, 256 bits)").source, TimingSource::CpuFinish);
    EXPECT_EQ(chooseTimingMethod("softpipe").source, TimingSource::CpuFinish);
    EXPECT_EQ(chooseTimingMethod("NVIDIA H200/PCIe/SSE2").source, TimingSource::GpuTimestamps);
    EXPECT_FALSE(chooseTimingMethod("llvmpipe").reason.empty());
}

// The same renderers mask branches (GlCaps::masksBranches), and GBL_SHADER_BRANCHES overrides.
TEST(BranchMasking, SoftwareRasterisersMaskBranchesUnlessOverridden) {
    EXPECT_TRUE(rendererMasksBranches("llvmpipe (LLVM 15.0.6, 256 bits)", nullptr));
    EXPECT_TRUE(rendererMasksBranches("softpipe", nullptr));
    EXPECT_FALSE(rendererMasksBranches("NVIDIA H200/PCIe/SSE2", nullptr));
    EXPECT_FALSE(rendererMasksBranches("llvmpipe (LLVM 15.0.6, 256 bits)", "skipping"));
    EXPECT_TRUE(rendererMasksBranches("NVIDIA H200/PCIe/SSE2", "masked"));
    EXPECT_TRUE(rendererMasksBranches("llvmpipe", "anything else: detect"));
}

// Unwaited frames report an earlier frame's times: with two kinds of frame rendered in turn (the
// A/B view's sides), each must get its own kind's, whichever GL queries time them. Before the
// timer kept streams, side B showed A's passes of the frame before, and A showed B's.
TEST_F(PassTimingGlTest, AlternatingStreamsEachReportTheirOwnPasses) {
    for (TimingSource const source : {TimingSource::GpuTimestamps, TimingSource::GpuElapsed}) {
        SCOPED_TRACE(std::string(timingSourceName(source)));
        GpuTimer timer;
        timer.force(source, "test");
        int reportedA = 0, reportedB = 0;
        // The passes issue no GL work: the queries alone are what is under test.
        for (int frame = 0; frame < 6; ++frame) {
            timer.begin("b-only");
            auto const b = timer.finishFrame(false, 1);
            timer.begin("a-first");
            timer.begin("a-second");
            auto const a = timer.finishFrame(false, 0);
            glFinish();  // the next frame's reads find these results
            if (!b.empty()) {
                ++reportedB;
                ASSERT_EQ(b.size(), 1u);
                EXPECT_EQ(b[0].first, "b-only");
                EXPECT_GE(b[0].second, 0.0);
            }
            if (!a.empty()) {
                ++reportedA;
                ASSERT_EQ(a.size(), 2u);
                EXPECT_EQ(a[0].first, "a-first");
                EXPECT_EQ(a[1].first, "a-second");
            }
        }
        // Each frame's results exist by the next frame: only the first frame has none to show.
        EXPECT_EQ(reportedA, 5);
        EXPECT_EQ(reportedB, 5);
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
        // A waited frame has its own results at once.
        timer.begin("waited");
        auto const waited = timer.finishFrame(true, 0);
        ASSERT_EQ(waited.size(), 1u);
        EXPECT_EQ(waited[0].first, "waited");
    }
}

TEST_F(PassTimingGlTest, StatsNameTheTimingSource) {
    std::vector<PointLight> const l = lights(4);
    FrameStats const s = renderer_->render({camera_, l, settings_, true});
    EXPECT_EQ(s.timingSource, timingSourceName(chooseTimingMethod(caps().renderer).source));
    EXPECT_FALSE(s.timingReason.empty());
}

TEST_F(PassTimingGlTest, PassesSumToAtMostTheWallTimeAndTheHeavierPassGrows) {
    Timed const light = measure(1);
    Timed const heavy = measure(512);
    double const lightingGrowth = heavy.lighting - light.lighting;
    // 512 lights at every one of 57,600 pixels are ~29M light-pixel pairs, at least ~100 ms on
    // any software rasteriser (a few ns per pair); a GPU does them in well under that, so there
    // only the direction is checked.
    bool const software = chooseTimingMethod(caps().renderer).source == TimingSource::CpuFinish;
    if (software) {
        EXPECT_GT(lightingGrowth, 50.0) << "lighting " << light.lighting << " -> " << heavy.lighting;
    }
    EXPECT_GT(lightingGrowth, 0.0);
    // The geometry pass did not change: whatever it grew by (machine noise) must be a small
    // part of what lighting grew by. Before, llvmpipe billed the lighting work to both.
    EXPECT_LT(heavy.geometry - light.geometry, 0.25 * lightingGrowth)
        << "geometry " << light.geometry << " -> " << heavy.geometry << ", lighting " << light.lighting << " -> "
        << heavy.lighting;
}

TEST_F(PassTimingGlTest, TheFrameHookBetweenPassesIsBilledToNeither) {
    // Work issued outside every bracket (here, between geometry and lighting) must not show up
    // in the pass times: the hook draws nothing but waits, as an untimed pass would.
    Timed const before = measure(8);
    RendererTestAccess::setFrameHook(*renderer_, [] {
        auto const until = std::chrono::steady_clock::now() + std::chrono::milliseconds(150);
        while (std::chrono::steady_clock::now() < until) {
        }
    });
    Timed const after = measure(8);
    RendererTestAccess::setFrameHook(*renderer_, {});
    EXPECT_LT(after.geometry, before.geometry + 100.0);
    EXPECT_LT(after.lighting, before.lighting + 100.0);
}

}  // namespace

// What each pass issued (gl/draw_count.h), per frame: the geometry pass one draw per mesh instance
// whatever the light count; quad and volumes light with draws, tiled with compute dispatches; the
// display pass one full-screen draw. The calls name the passes that ran, in order.
TEST_F(PassTimingGlTest, EachPassCountsTheDrawsAndDispatchesItIssued) {
    auto const callsOf = [](FrameStats const& s, std::string const& name) {
        PassCalls sum{name};
        bool found = false;
        for (PassCalls const& c : s.calls) {
            if (c.name != name) continue;
            sum.draws += c.draws;
            sum.dispatches += c.dispatches;
            found = true;
        }
        EXPECT_TRUE(found) << "no calls for " << name;
        return sum;
    };
    for (int count : {4, 32}) {
        FrameStats const s = renderer_->render({camera_, lights(count), settings_, true});
        ASSERT_EQ(s.calls.size(), s.passes.size());
        for (std::size_t i = 0; i < s.calls.size(); ++i) EXPECT_EQ(s.calls[i].name, s.passes[i].name);
        EXPECT_EQ(callsOf(s, "geometry").draws, scene_.instances.size()) << count << " lights";
        EXPECT_EQ(callsOf(s, "geometry").dispatches, 0u);
        EXPECT_GE(callsOf(s, "lighting").draws, 1u);
        EXPECT_EQ(callsOf(s, "display").draws, 1u);
    }
    // Volumes: instanced, so the draws do not grow with the lights.
    settings_.mode = LightingMode::Volumes;
    std::uint64_t const few = callsOf(renderer_->render({camera_, lights(4), settings_, true}), "lighting").draws;
    std::uint64_t const many = callsOf(renderer_->render({camera_, lights(64), settings_, true}), "lighting").draws;
    EXPECT_GE(few, 1u);
    EXPECT_EQ(few, many);
    if (renderer_->caps().computeShaders) {
        settings_.mode = LightingMode::Tiled;
        FrameStats const s = renderer_->render({camera_, lights(32), settings_, true});
        EXPECT_GE(callsOf(s, "light_lists").dispatches, 1u);
        EXPECT_EQ(callsOf(s, "light_lists").draws, 0u);
        EXPECT_GE(callsOf(s, "lighting").dispatches, 1u);
    }
}

// Every draw and dispatch in renderer/ counts itself: the line after each glDraw* (not
// glDrawBuffer[s]) or glDispatchCompute call is its gl::countDraw(triangles) / gl::countDispatch().
// Declarations and definitions (a return type before the name) are not call sites.
TEST(DrawCount, EveryCallSiteInTheRendererCountsItself) {
    std::regex const call(R"(\bgl(Draw(Arrays|Elements|RangeElements)\w*|DispatchCompute\w*)\s*\()");
    int sites = 0;
    for (auto const& entry : std::filesystem::recursive_directory_iterator(gbl::test::sourcePath("renderer"))) {
        std::string const ext = entry.path().extension().string();
        if (ext != ".cpp" && ext != ".h") continue;
        std::ifstream in(entry.path());
        std::vector<std::string> lines;
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        for (std::size_t i = 0; i < lines.size(); ++i) {
            std::smatch m;
            if (!std::regex_search(lines[i], m, call)) continue;
            // A declaration or definition (the browser build's stand-ins, gl/gl_web*.h/.cpp) is not a call.
            if (m.prefix().str().find("void ") != std::string::npos) continue;
            ++sites;
            bool const dispatch = m.str(1).rfind("Dispatch", 0) == 0;
            std::string const next = i + 1 < lines.size() ? lines[i + 1] : "";
            EXPECT_NE(next.find(dispatch ? "countDispatch()" : "countDraw("), std::string::npos)
                << entry.path().string() << ":" << i + 1 << " is not counted: " << lines[i];
        }
    }
    EXPECT_GE(sites, 11);  // the renderer's call sites when this test was written
}
