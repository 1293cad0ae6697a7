// Every step of every shipped lesson rendered headlessly, its claim checked on real read-back
// values; and each claim kind shown to fail when what it says is false.
#include "core/pipeline_fields.h"
#include "gl_fixture.h"
#include "lesson_render.h"
#include "model/lesson_text.h"
#include "scene/default_scene.h"
#include "session/lesson_file.h"
#include "test_paths.h"

#include <epoxy/gl.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>

using namespace gbl;
using gbl::test::GlTest;

namespace {

std::string shippedDir() {
    return gbl::test::sourcePath("assets/lessons");
}

class LessonsGlTest : public GlTest {
protected:
    static ui::LessonLibrary const& library() {
        static ui::LessonLibrary const lib = ui::loadLessonDir(shippedDir());
        return lib;
    }
    static ui::Lesson const& lesson(std::string const& id) {
        for (auto const& l : library().lessons)
            if (l.id == id) return l;
        throw std::runtime_error("no shipped lesson " + id);
    }
    // Renders one step on a renderer of the lesson's size (or `size`: the student's frame) with the
    // step's default scene.
    LessonStepFrame render(ui::Lesson const& l, ui::LessonStep const& step, glm::ivec2 size = {0, 0}) {
        if (size.x <= 0) size = {l.width, l.height};
        auto& r = renderers_[{size.x, size.y}];
        if (!r) r = makeRenderer(size.x, size.y);
        int const scene = (step.defaultSceneLights + 1) * 2 + int(step.defaultSceneGlass);
        if (sceneLights_[r.get()] != scene) {
            EXPECT_FALSE(r->setScene(makeDefaultScene({step.defaultSceneLights, step.defaultSceneGlass})));
            sceneLights_[r.get()] = scene;
        }
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
        LessonStepFrame f = renderLessonStep(*r, step);
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
        EXPECT_EQ(f.stats.glErrors, 0u);
        return f;
    }
    void TearDown() override {
        renderers_.clear();
        GlTest::TearDown();
    }
    std::map<std::pair<int, int>, std::unique_ptr<Renderer>> renderers_;
    std::map<Renderer*, int> sceneLights_;  // (lights + 1) * 2 + glass of the scene it holds
};

TEST_F(LessonsGlTest, TheShippedLessonsLoadAndFollowTheIssue) {
    EXPECT_TRUE(library().errors.empty()) << (library().errors.empty() ? "" : library().errors.front());
    ASSERT_GE(library().lessons.size(), 10u);
    for (auto const& l : library().lessons) {
        EXPECT_GE(l.steps.size(), 3u) << l.id;
        EXPECT_LE(l.steps.size(), 6u) << l.id;
        for (std::size_t i = 0; i < l.steps.size(); ++i) EXPECT_TRUE(l.steps[i].claim) << l.id << ":" << i + 1;
    }
}

TEST_F(LessonsGlTest, EveryStepsClaimHoldsOnTheRealFrame) {
    int checked = 0;
    for (auto const& l : library().lessons) {
        for (std::size_t i = 0; i < l.steps.size(); ++i) {
            ui::LessonStep const& step = l.steps[i];
            if (step.state.pipeline.mode == LightingMode::Tiled && !caps().computeShaders) continue;
            LessonStepFrame const f = render(l, step);
            EXPECT_EQ(f.stats.modeUsed, step.state.pipeline.mode)
                << l.id << ":" << i + 1 << " " << f.stats.fallbackReason;
            ASSERT_TRUE(f.claim) << l.id << ":" << i + 1;
            EXPECT_TRUE(f.claim->holds) << l.id << ":" << i + 1 << " (" << step.text.title << "): " << f.claim->detail;
            if (std::getenv("GBL_LESSON_DETAILS"))
                std::printf("%s:%zu %dx%d %s\n", l.id.c_str(), i + 1, l.width, l.height, f.claim->detail.c_str());
            ++checked;
        }
    }
    EXPECT_GE(checked, 30);
}

// The lessons' own size and the student's frames (below).
constexpr std::array<glm::ivec2, 3> kStudentSizes{{{480, 270}, {641, 407}, {800, 535}}};

// The frame the student sees is not the lessons' 480x270: the editor's viewport at 1280x720 is 641x407
// and at 1600x900 800x535 (measured with --log-frames' frameSize at UI scale 1). Every step's claim,
// and so every number its text states (each bounded by its claim), holds there too.
TEST_F(LessonsGlTest, EveryStepsClaimHoldsOnTheStudentsFrame) {
    for (glm::ivec2 const size : {kStudentSizes[1], kStudentSizes[2]}) {
        int checked = 0;
        for (auto const& l : library().lessons) {
            for (std::size_t i = 0; i < l.steps.size(); ++i) {
                ui::LessonStep const& step = l.steps[i];
                if (step.state.pipeline.mode == LightingMode::Tiled && !caps().computeShaders) continue;
                LessonStepFrame const f = render(l, step, size);
                ASSERT_TRUE(f.claim) << l.id << ":" << i + 1;
                EXPECT_TRUE(f.claim->holds) << l.id << ":" << i + 1 << " at " << size.x << "x" << size.y << " ("
                                            << step.text.title << "): " << f.claim->detail;
                if (std::getenv("GBL_LESSON_DETAILS"))
                    std::printf("%s:%zu %dx%d %s\n", l.id.c_str(), i + 1, size.x, size.y, f.claim->detail.c_str());
                ++checked;
            }
        }
        EXPECT_GE(checked, 30);
    }
}

// position_from_depth:2 asks the student to lock a pixel where the reconstruction error is largest:
// the frame's largest error lies in the task's region, and the step's own pixel does not.
TEST_F(LessonsGlTest, ThePixelTaskRegionHoldsTheLargestPositionError) {
    ui::Lesson const& l = lesson("position_from_depth");
    ui::LessonStep const& step = l.steps.at(1);
    ASSERT_EQ(step.tasks.size(), 1u);
    ASSERT_EQ(step.tasks[0].kind, ui::TaskKind::Pixel);
    for (glm::ivec2 const size : kStudentSizes) {
        LessonStepFrame const f = render(l, step, size);
        ASSERT_TRUE(f.claim && f.claim->worst) << (f.claim ? f.claim->detail : "no claim");
        ui::TaskContext ctx;
        ctx.pixelLocked = true;
        ctx.frameSize = size;
        ctx.lessonSize = {l.width, l.height};
        ctx.pixel = *f.claim->worst;
        EXPECT_TRUE(ui::taskMet(step.tasks[0], ctx)) << size.x << "x" << size.y << ": " << f.claim->detail;
        ctx.pixel = f.pixel;
        EXPECT_FALSE(ui::taskMet(step.tasks[0], ctx));
    }
}

// The step rings that pixel (its claim's `mark`, which the editor measures on its own frame): the
// mark is the claim's largest error, its value within the claim's range and printed in its label,
// and the step's task is met there. A claim without `mark` marks nothing.
TEST_F(LessonsGlTest, ThePositionErrorStepMarksItsLargestError) {
    ui::Lesson const& l = lesson("position_from_depth");
    ui::LessonStep const& step = l.steps.at(1);
    ASSERT_TRUE(step.claim && step.claim->mark);
    LessonStepFrame const f = render(l, step);
    ASSERT_TRUE(f.claim && f.claim->worst) << (f.claim ? f.claim->detail : "no claim");
    std::optional<ui::ClaimMark> const m = ui::claimMark(*step.claim, *f.claim);
    ASSERT_TRUE(m);
    EXPECT_EQ(m->pixel, *f.claim->worst);
    EXPECT_GE(m->value, step.claim->atLeast);
    EXPECT_LT(m->value, step.claim->bound);
    EXPECT_NE(m->label.find(ui::lessonNumber(m->value)), std::string::npos) << m->label;
    ui::TaskContext ctx;
    ctx.pixelLocked = true;
    ctx.frameSize = ctx.lessonSize = {l.width, l.height};
    ctx.pixel = m->pixel;
    EXPECT_TRUE(ui::taskMet(step.tasks.at(0), ctx));
    ui::LessonClaim plain = *step.claim;
    plain.mark = false;
    EXPECT_FALSE(ui::claimMark(plain, *f.claim));
}

// The shipped setting tasks, done on the real frame: the step's state with the task's value shows
// what the task is about (a light lost, cubes through walls, no light cut off).
TEST_F(LessonsGlTest, SettingTasksShowTheirPointOnTheRealFrame) {
    // step, what the done task's frame must show against `reference` (the done state, changed)
    struct Case {
        std::string lesson;
        int step;
        std::function<void(ui::LessonClaim&, PipelineSettings&)> claim;
    };
    std::vector<Case> const cases{
        {"camera_inside", 3,  // cull back loses light 0: the light is back with cull front
         [](ui::LessonClaim& c, PipelineSettings& ref) {
             c.kind = ui::ClaimKind::LosesLight;
             c.light = 0;
             c.tolerance = 0.03f;
             ref.cull = CullMode::Front;
         }},
        {"depth_blit", 3,  // the copy off: cubes over walls the blit hides (on the display: an overlay)
         [](ui::LessonClaim& c, PipelineSettings& ref) {
             c.kind = ui::ClaimKind::DiffersFrom;
             c.image = Attachment::Final;
             c.bound = 0.05f;
             c.minFraction = 0.01f;  // step 3's column view: the cubes cover over 1 % of the frame
             ref.depthCopy = DepthCopy::Blit;
         }},
        {"light_volumes", 1,  // the enclosing scale loses nothing: the full-screen pass's image
         [](ui::LessonClaim& c, PipelineSettings& ref) {
             c.kind = ui::ClaimKind::SameImage;
             c.bound = 0.01f;
             ref.mode = LightingMode::Quad;
         }},
    };
    for (Case const& k : cases) {
        ui::Lesson const& l = lesson(k.lesson);
        ui::LessonStep step = l.steps.at(std::size_t(k.step));
        ASSERT_EQ(step.tasks.size(), 1u) << k.lesson;
        ui::LessonTask const& t = step.tasks[0];
        ASSERT_EQ(t.kind, ui::TaskKind::Setting) << k.lesson;
        PipelineField const* field = findPipelineField(t.setting);
        ASSERT_TRUE(field) << t.setting;
        field->set(step.state.pipeline, t.value);  // the task done
        PipelineSettings reference = step.state.pipeline;
        step.claim = ui::LessonClaim{};
        k.claim(*step.claim, reference);
        step.claim->reference = reference;
        for (glm::ivec2 const size : kStudentSizes) {
            LessonStepFrame const f = render(l, step, size);
            ASSERT_TRUE(f.claim);
            EXPECT_TRUE(f.claim->holds) << k.lesson << ":" << k.step + 1 << " with " << t.setting << " done at "
                                        << size.x << "x" << size.y << ": " << f.claim->detail;
        }
    }
}

// light_volumes:2 says a volume scale just below 1 still cuts a thin rim, "about a thousandth of the
// lit pixels" at 0.95, and 1 cuts nothing (the SameImage case above), on every frame size the
// student may have.
TEST_F(LessonsGlTest, AVolumeScaleJustBelowOneLosesAVisibleRim) {
    ui::Lesson const& l = lesson("light_volumes");
    ui::LessonStep step = l.steps.at(1);
    ASSERT_EQ(step.claim->kind, ui::ClaimKind::FewerLitPixels);
    ASSERT_TRUE(step.claim->reference);
    EXPECT_EQ(step.claim->reference->volumeScale, 1.0f);
    step.state.pipeline.volumeScale = 0.95f;
    // 0.12 to 0.13 % measured at the three sizes: 0.05 % is "about a thousandth" rounded down far
    // enough for fp16 noise, and still 65 pixels at 480x270.
    step.claim->minFraction = 0.0005f;
    for (glm::ivec2 const size : kStudentSizes) {
        LessonStepFrame const f = render(l, step, size);
        EXPECT_TRUE(f.claim->holds) << size.x << "x" << size.y << ": " << f.claim->detail;
    }
    // Not more than "about a thousandth": 0.3 % lost would fail.
    step.claim->minFraction = 0.003f;
    EXPECT_FALSE(render(l, step).claim->holds);
}

// executed_vs_lit:3's tasks (volumes with the stencil cull) bring the pixel's two heat-map counts
// closest, as their goal says: fewer wasted evaluations there than the step's tiled mode, and than
// step 2's cull front.
TEST_F(LessonsGlTest, TheStencilTaskWastesLeastAtThePixel) {
    ui::Lesson const& l = lesson("executed_vs_lit");
    ui::LessonStep const& tiled = l.steps.at(2);
    ui::LessonStep stencil = tiled;
    ASSERT_EQ(stencil.tasks.size(), 2u);
    for (ui::LessonTask const& t : stencil.tasks) {
        PipelineField const* field = findPipelineField(t.setting);
        ASSERT_TRUE(field) << t.setting;
        field->set(stencil.state.pipeline, t.value);
    }
    EXPECT_EQ(stencil.state.pipeline.mode, LightingMode::Volumes);
    EXPECT_EQ(stencil.state.pipeline.cull, CullMode::Stencil);
    ui::LessonStep front = stencil;
    front.state.pipeline.cull = CullMode::Front;
    for (glm::ivec2 const size : kStudentSizes) {
        auto wasted = [&](ui::LessonStep const& s) {
            LessonStepFrame const f = render(l, s, size);
            FloatImage const c = renderers_[{size.x, size.y}]->readAttachment(Attachment::Coverage);
            EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
            return c.at(f.pixel.x, f.pixel.y, 0) - c.at(f.pixel.x, f.pixel.y, 1);  // evaluated - lit
        };
        float const s = wasted(stencil), t = wasted(tiled), fr = wasted(front);
        EXPECT_LT(s, t) << size.x << "x" << size.y;
        EXPECT_LE(s, fr) << size.x << "x" << size.y;
        EXPECT_GE(s, 0.0f);
    }
}

// --- each claim kind fails when its statement is false ------------------------------------------

ui::LessonStep withClaim(ui::LessonStep step, std::function<void(ui::LessonClaim&)> const& change) {
    change(*step.claim);
    return step;
}

TEST_F(LessonsGlTest, LosesLightFailsWhenTheReferenceLosesItToo) {
    ui::Lesson const& l = lesson("camera_inside");
    ui::LessonStep const back = l.steps[1];
    ASSERT_EQ(back.claim->kind, ui::ClaimKind::LosesLight);
    auto const f = render(l, withClaim(back, [&](ui::LessonClaim& c) { c.reference = back.state.pipeline; }));
    EXPECT_FALSE(f.claim->holds) << f.claim->detail;
}

TEST_F(LessonsGlTest, MatchesCpuFailsWhereALightIsLost) {
    ui::Lesson const& l = lesson("camera_inside");
    ui::LessonStep step = l.steps[1];  // cull back from inside
    step.claim = ui::LessonClaim{};
    step.claim->kind = ui::ClaimKind::MatchesCpu;
    step.claim->tolerance = 0.02f;
    auto const f = render(l, step);
    EXPECT_FALSE(f.claim->holds) << f.claim->detail;
}

TEST_F(LessonsGlTest, SameImageAndDiffersFromAreOpposites) {
    ui::Lesson const& l = lesson("camera_inside");
    ui::LessonStep const front = l.steps[0];
    ui::LessonStep step = front;
    PipelineSettings back = front.state.pipeline;
    back.cull = CullMode::Back;
    step.claim = ui::LessonClaim{};
    step.claim->kind = ui::ClaimKind::SameImage;
    step.claim->reference = back;
    step.claim->bound = 0.01f;
    EXPECT_FALSE(render(l, step).claim->holds);
    step.claim->kind = ui::ClaimKind::DiffersFrom;
    step.claim->minFraction = 0.05f;
    EXPECT_TRUE(render(l, step).claim->holds);
    step.claim->reference = front.state.pipeline;
    EXPECT_FALSE(render(l, step).claim->holds);
}

// differs_from's max_fraction bounds the share from above: depth_blit:3's cubes fail a range that
// ends below their share, and hold in the step's own.
TEST_F(LessonsGlTest, DiffersFromFailsAboveItsMaxFraction) {
    ui::Lesson const& l = lesson("depth_blit");
    ui::LessonStep const& step = l.steps.at(2);
    ASSERT_TRUE(step.claim && step.claim->kind == ui::ClaimKind::DiffersFrom);
    EXPECT_TRUE(render(l, step).claim->holds);
    auto const f = render(l, withClaim(step, [](ui::LessonClaim& c) {
                              c.minFraction = 0.001f;
                              c.maxFraction = 0.005f;
                          }));
    EXPECT_FALSE(f.claim->holds) << f.claim->detail;
}

// fewer_evaluations compares the heat map's sums: the stencil step against itself saves nothing,
// and cull front against the stencil runs more, not fewer.
TEST_F(LessonsGlTest, FewerEvaluationsFailsAgainstItselfAndTheOtherWayRound) {
    ui::Lesson const& l = lesson("light_volumes");
    ui::LessonStep const& step = l.steps.at(3);
    ASSERT_TRUE(step.claim && step.claim->kind == ui::ClaimKind::FewerEvaluations);
    auto const own = render(l, step);
    ASSERT_TRUE(own.claim);
    EXPECT_TRUE(own.claim->holds) << own.claim->detail;
    auto const self = render(l, withClaim(step, [&](ui::LessonClaim& c) { c.reference = step.state.pipeline; }));
    EXPECT_FALSE(self.claim->holds) << self.claim->detail;
    ui::LessonStep front = step;
    front.state.pipeline.cull = CullMode::Front;
    auto const reversed = render(l, withClaim(front, [&](ui::LessonClaim& c) { c.reference = step.state.pipeline; }));
    EXPECT_FALSE(reversed.claim->holds) << reversed.claim->detail;
}

TEST_F(LessonsGlTest, FewerLitPixelsFailsAgainstItself) {
    ui::Lesson const& l = lesson("light_volumes");
    ui::LessonStep const small = l.steps[1];
    ASSERT_EQ(small.claim->kind, ui::ClaimKind::FewerLitPixels);
    auto const f = render(l, withClaim(small, [&](ui::LessonClaim& c) { c.reference = small.state.pipeline; }));
    EXPECT_FALSE(f.claim->holds) << f.claim->detail;
}

TEST_F(LessonsGlTest, PositionErrorFailsBelowTheFloatPrecision) {
    ui::Lesson const& l = lesson("position_from_depth");
    // 1e-6 units is far below what a 16-bit float position holds at metres from the origin.
    auto const f = render(l, withClaim(l.steps[1], [](ui::LessonClaim& c) { c.bound = 1e-6f; }));
    EXPECT_FALSE(f.claim->holds) << f.claim->detail;
}

// at_least makes the claim a range: the shipped step's largest error (about 0.02, position_from_depth:4's
// text) fails a floor just above it, and the step's own floor is below it.
TEST_F(LessonsGlTest, PositionErrorFailsAboveTheLargestError) {
    ui::Lesson const& l = lesson("position_from_depth");
    ui::LessonStep const& step = l.steps[3];
    ASSERT_GT(step.claim->atLeast, 0.0f) << "position_from_depth:4 states its largest error";
    auto const good = render(l, step);
    ASSERT_TRUE(good.claim->holds) << good.claim->detail;
    auto const f = render(l, withClaim(step, [](ui::LessonClaim& c) {
                              c.atLeast = 0.022f;
                              c.bound = 1.0f;
                          }));
    EXPECT_FALSE(f.claim->holds) << f.claim->detail;
}

TEST_F(LessonsGlTest, AttachmentEqualsFailsForAnotherNormal) {
    ui::Lesson const& l = lesson("gbuffer");
    auto const f = render(l, withClaim(l.steps[2], [](ui::LessonClaim& c) { c.value = {1.0f, 0.0f, 0.0f, 0.0f}; }));
    EXPECT_FALSE(f.claim->holds) << f.claim->detail;
}

TEST_F(LessonsGlTest, TileCountFailsWhenTheCpuSeesOtherLights) {
    if (!caps().computeShaders) GTEST_SKIP() << caps().tiledUnavailableReason();
    ui::Lesson const& l = lesson("tiled");
    ui::LessonStep step = l.steps[1];
    ASSERT_EQ(step.claim->kind, ui::ClaimKind::TileCountMatchesCpu);
    LessonStepFrame const good = render(l, step);
    ASSERT_TRUE(good.claim->holds) << good.claim->detail;
    // The claim checks the frame's own lights; a frame rendered without some of them lists fewer.
    step.state.lights.resize(step.state.lights.size() / 2);
    auto& r = renderers_[{l.width, l.height}];
    ui::LessonStep full = l.steps[1];
    r->render({step.state.camera, step.state.lights, step.state.pipeline, true});
    ui::ClaimImages im;
    im.position = r->readAttachment(Attachment::Position);
    im.depth = r->readAttachment(Attachment::Depth);
    im.coverage = r->readAttachment(Attachment::Coverage);
    auto const bad =
        ui::checkClaim(*full.claim, {full.state.camera, full.state.lights, full.state.pipeline, good.pixel}, im);
    EXPECT_FALSE(bad.holds) << bad.detail;
}

// most: tiled:3's tile lists the most lights of the frame; step 2's floor tile, with the same claim, does not.
TEST_F(LessonsGlTest, TileCountMostFailsOnAFloorTile) {
    if (!caps().computeShaders) GTEST_SKIP() << caps().tiledUnavailableReason();
    ui::Lesson const& l = lesson("tiled");
    ASSERT_TRUE(l.steps[2].claim->most) << "tiled:3 says its tile lists the most";
    ui::LessonStep step = l.steps[1];
    auto const f = render(l, withClaim(step, [](ui::LessonClaim& c) { c.most = true; }));
    EXPECT_FALSE(f.claim->holds) << f.claim->detail;
}

TEST_F(LessonsGlTest, ExecutedExceedsLitFailsWithOneLightThatReachesThePixel) {
    ui::Lesson const& l = lesson("executed_vs_lit");
    ui::LessonStep step = l.steps[0];  // quad heat map
    // One light over the pixel's surface, large enough to reach it: evaluated 1, lit 1.
    auto const floor = render(l, step);
    ASSERT_TRUE(floor.claim->holds) << floor.claim->detail;
    PointLight big;
    big.position = {0.0f, 2.0f, 4.0f};
    big.kl = 0.0f;
    big.kq = 0.01f;
    step.state.lights = {big};
    auto const f = render(l, withClaim(step, [](ui::LessonClaim& c) {
                              c.minFraction = 0.0f;  // the pixel alone, not the frame's share
                              c.maxFraction = 1.0f;
                          }));
    EXPECT_FALSE(f.claim->holds) << f.claim->detail;
}

// The frame-wide share: the full-screen pass's waste (executed_vs_lit:1's range) is not the tiled
// pass's, which evaluates only the lights its tile lists.
TEST_F(LessonsGlTest, ExecutedExceedsLitFailsOutsideItsWastedShare) {
    if (!caps().computeShaders) GTEST_SKIP() << caps().tiledUnavailableReason();
    ui::Lesson const& l = lesson("executed_vs_lit");
    ui::LessonClaim const quadRange = *l.steps[0].claim;
    ASSERT_GT(quadRange.minFraction, 0.0f);
    auto const f = render(l, withClaim(l.steps[2], [&](ui::LessonClaim& c) {
                              c.minFraction = quadRange.minFraction;
                              c.maxFraction = quadRange.maxFraction;
                          }));
    EXPECT_FALSE(f.claim->holds) << f.claim->detail;
}

}  // namespace
