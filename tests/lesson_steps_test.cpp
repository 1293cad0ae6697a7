// Lesson steps on the CPU: the shipped steps' numbers and claims agree with their text, every
// shipped question has an answer, placeholders take live values, and a step applied in the editor
// (its A/B split too) is undone by leaving and is one undo entry. The file format: lesson_file_test.
#include "core/light_math.h"
#include "lesson_samples.h"
#include "model/lesson_claims.h"
#include "model/lesson_state.h"
#include "model/lesson_text.h"
#include "model/undo.h"
#include "scene/default_scene.h"
#include "session/lesson_file.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <regex>
#include <string>

using namespace gbl;
using namespace gbl::ui;
using gbl::test::lessonError;
using gbl::test::minimalLesson;
using gbl::test::shippedStep;
using nlohmann::json;

// Every question of every shipped lesson has an answer to reveal (issue 27), and every shipped
// lesson reads without an error.
TEST(LessonFile, EveryShippedQuestionHasAnAnswer) {
    LessonLibrary const lib = loadLessonDir(defaultLessonDir());
    EXPECT_TRUE(lib.errors.empty()) << lib.errors.front();
    EXPECT_EQ(lib.lessons.size(), 13u);  // 11 and 12 (issue 47), 13 (issue 48)
    int questions = 0;
    for (Lesson const& l : lib.lessons)
        for (std::size_t i = 0; i < l.steps.size(); ++i) {
            LessonText const& t = l.steps[i].text;
            if (t.question.empty()) continue;
            ++questions;
            EXPECT_GE(t.answer.size(), 40u) << l.id << ":" << i + 1 << " has no real answer: \"" << t.answer << "\"";
            EXPECT_NE(t.answer, t.question) << l.id << ":" << i + 1;
        }
    EXPECT_GE(questions, 37);
    // The raw files too: a step with a question and no "answer" field fails to load (above), so
    // a lesson dropped from the library would show up as an error, not as a missing answer.
}

// The depth_blit lesson is about the light cubes, which are an overlay on the display image (not in
// the lit image): its claims compare the final image; a bad "image" names the field.
// attenuation:2 states its numbers in text (the prediction's state has no placeholders for the light
// before the change): each is computed here from the step's lights, so editing a light without the
// text, or the text without the light, fails.
TEST(LessonFile, TheAttenuationStepsNumbersAreItsLightsNumbers) {
    LessonStep const& step = shippedStep("attenuation:2");
    ASSERT_TRUE(step.predict && step.predict->before);
    PointLight const& before = step.predict->before->lights.at(0);
    PointLight const& after = step.state.lights.at(0);
    auto fixed = [](double v, int digits) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.*f", digits, v);
        return std::string(buf);
    };
    double const rBefore = lightRadius(before).radius;
    double const rAfter = lightRadius(after).radius;
    double const kqRatio = double(after.kq) / double(before.kq);
    double const imax = double(std::max({before.color.r, before.color.g, before.color.b})) * before.intensity;
    double const budget = imax / double(before.threshold);  // Imax·256/5
    auto expectIn = [](std::string const& text, std::string const& part, char const* where) {
        EXPECT_NE(text.find(part), std::string::npos) << where << " should say \"" << part << "\": " << text;
    };
    LessonText const& t = step.text;
    expectIn(t.look, "Kq raised from " + fixed(before.kq, 2) + " to " + fixed(after.kq, 1), "look");
    expectIn(t.look, "(" + fixed(kqRatio, 2) + " times)", "look");
    expectIn(t.look, "shrinks from " + fixed(rBefore, 2) + " to {light.radius}", "look");
    expectIn(t.question, "from " + fixed(rBefore, 2) + " to {light.radius}", "question");
    expectIn(t.question, "Kq grew " + fixed(kqRatio, 2) + " times", "question");
    expectIn(t.question, "the " + fixed(std::sqrt(kqRatio), 2) + " that 1/√" + fixed(kqRatio, 2) + " gives",
             "question");
    // "almost exactly half": the radii's ratio is 2 within 2 %.
    EXPECT_NEAR(rBefore / rAfter, 2.0, 0.04);
    expectIn(t.answer, fixed(rBefore / rAfter, 2) + " times smaller", "answer");
    expectIn(t.answer,
             "(Kq·d² = " + fixed(before.kq * rBefore * rBefore, 1) + " of " + fixed(budget, 1) +
                 " at r = " + fixed(rBefore, 2) + ")",
             "answer");
    expectIn(t.answer,
             "Kq × " + fixed(kqRatio, 2) + " gives r ÷ √" + fixed(kqRatio, 2) + " = ÷ " + fixed(std::sqrt(kqRatio), 2),
             "answer");
    expectIn(t.answer, "(" + fixed(before.kl * rBefore, 1) + " against " + fixed(after.kl * rAfter, 1) + ")", "answer");
    expectIn(t.answer, "below " + fixed(std::sqrt(kqRatio), 2) + ", to " + fixed(rBefore / rAfter, 2), "answer");
    // The linear term's larger share is why the factor is below √ratio: the text's explanation holds.
    EXPECT_LT(rBefore / rAfter, std::sqrt(kqRatio));
    // The prediction: the radius before, and the right number is the radius after.
    expectIn(step.predict->prompt, "from " + fixed(before.kq, 2) + " to " + fixed(after.kq, 1), "prompt");
    expectIn(step.predict->prompt, "The radius is " + fixed(rBefore, 2) + " now", "prompt");
    EXPECT_NEAR(step.predict->number, rAfter, 0.005);
    expectIn(step.predict->explain, fixed(rBefore, 2) + " → {light.radius}", "explain");
}

TEST(LessonFile, TheDepthBlitClaimsCompareTheDisplayImage) {
    LessonLibrary const lib = loadLessonDir(defaultLessonDir());
    auto const it =
        std::find_if(lib.lessons.begin(), lib.lessons.end(), [](Lesson const& l) { return l.id == "depth_blit"; });
    ASSERT_NE(it, lib.lessons.end());
    int claims = 0;
    for (LessonStep const& step : it->steps)
        if (step.claim) {
            EXPECT_EQ(step.claim->image, Attachment::Final);
            ++claims;
        }
    EXPECT_EQ(claims, 4);
    json j = minimalLesson();
    j["steps"][0]["claim"] = {
        {"kind", "same_image"}, {"reference", {{"blit", "off"}}}, {"bound", 0.0}, {"image", "hdr"}};
    std::string const e = lessonError(j);
    EXPECT_EQ(e.rfind("demo.json: steps[0].claim.image must be lighting or final", 0), 0u) << e;
}

// depth_blit:3 says how many of the frame's pixels its cubes through the column change ("about
// 1.5 %"): its claim checks that share as a range, and the text's number lies in it. A max_fraction
// not above min_fraction is refused.
TEST(LessonFile, TheCubesThroughTheColumnShareIsTheClaimsRange) {
    LessonStep const& step = shippedStep("depth_blit:3");
    ASSERT_TRUE(step.claim && step.claim->kind == ClaimKind::DiffersFrom);
    EXPECT_LT(step.claim->maxFraction, 1.0f);
    int stated = 0;
    for (std::string const* text : {&step.text.look, &step.text.answer}) {
        std::smatch m;
        ASSERT_TRUE(std::regex_search(*text, m, std::regex(R"(about ([0-9.]+) %)"))) << *text;
        float const share = std::stof(m[1]) / 100.0f;
        EXPECT_GE(share, step.claim->minFraction) << m[0];
        EXPECT_LT(share, step.claim->maxFraction) << m[0];
        ++stated;
    }
    EXPECT_EQ(stated, 2);
    json j = minimalLesson();
    j["steps"][0]["claim"] = {{"kind", "differs_from"},
                              {"reference", {{"blit", "off"}}},
                              {"bound", 0.0},
                              {"min_fraction", 0.2},
                              {"max_fraction", 0.1}};
    std::string const e = lessonError(j);
    EXPECT_EQ(e.rfind("demo.json: steps[0].claim.max_fraction must be greater than min_fraction", 0), 0u) << e;
}

// tiled:1 shows what is tile-related as it opens: the heat view split against quad, so the left
// (tiled) shows the lights each tile lists and the right (quad) every light at every pixel.
TEST(LessonFile, TheTiledStepSplitsLightsPerTileAgainstEveryLight) {
    LessonStep const& step = shippedStep("tiled:1");
    EXPECT_EQ(step.state.pipeline.mode, LightingMode::Tiled);
    EXPECT_EQ(step.state.pipeline.view, DebugView::Heatmap);
    ASSERT_TRUE(step.state.ab);
    EXPECT_EQ(step.state.ab->view, AbView::Split);
    EXPECT_EQ(step.state.ab->b.mode, LightingMode::Quad);
    ASSERT_TRUE(step.claim && step.claim->kind == ClaimKind::SameImage);
    EXPECT_EQ(step.claim->image, Attachment::Lighting);  // the lit frames, whatever the view
}

// light_volumes:4 shows what the stencil saves: the heat view split against cull front, and its
// text's saving ("about 17 %") lies in the range its fewer_evaluations claim checks. The kind needs
// the heat view and a max_fraction above min_fraction.
TEST(LessonFile, TheStencilStepsSavingIsTheClaimsRange) {
    LessonStep const& step = shippedStep("light_volumes:4");
    EXPECT_EQ(step.state.pipeline.cull, CullMode::Stencil);
    EXPECT_EQ(step.state.pipeline.view, DebugView::Heatmap);
    ASSERT_TRUE(step.state.ab);
    EXPECT_EQ(step.state.ab->view, AbView::Split);
    EXPECT_EQ(step.state.ab->b.cull, CullMode::Front);
    ASSERT_TRUE(step.claim && step.claim->kind == ClaimKind::FewerEvaluations);
    ASSERT_TRUE(step.claim->reference);
    EXPECT_EQ(step.claim->reference->cull, CullMode::Front);
    for (std::string const* text : {&step.text.look, &step.text.answer}) {
        std::smatch m;
        ASSERT_TRUE(std::regex_search(*text, m, std::regex(R"(about ([0-9.]+) %)"))) << *text;
        float const saved = std::stof(m[1]) / 100.0f;
        EXPECT_GE(saved, step.claim->minFraction) << m[0];
        EXPECT_LT(saved, step.claim->maxFraction) << m[0];
    }
    json j = minimalLesson();
    j["steps"][0]["claim"] = {{"kind", "fewer_evaluations"}, {"reference", {{"cull", "front"}}}, {"min_fraction", 0.1}};
    std::string e = lessonError(j);
    EXPECT_EQ(e.rfind("demo.json: steps[0].claim.kind needs pipeline.view \"heatmap\"", 0), 0u) << e;
    j["steps"][0]["pipeline"]["view"] = "heatmap";
    j["steps"][0]["claim"]["max_fraction"] = 0.05;
    e = lessonError(j);
    EXPECT_EQ(e.rfind("demo.json: steps[0].claim.max_fraction must be greater than min_fraction", 0), 0u) << e;
}

TEST(LessonFile, PlaceholdersAreSubstitutedWithLiveValues) {
    LessonValues v;
    PointLight l;
    l.kq = 0.44f;
    v.light = l;
    v.lightIndex = 3;
    v.lightCount = 7;
    EXPECT_EQ(substituteLessonText("light {light.index} Kq {light.kq} of {lights.count}", v), "light 3 Kq 0.44 of 7");
    EXPECT_EQ(
        substituteLessonText("r = {light.radius}", v), "r = " + [&] {
            char b[32];
            std::snprintf(b, sizeof b, "%.4g", double(lightRadius(l).radius));
            return std::string(b);
        }());
    EXPECT_EQ(substituteLessonText("{pixel.lit}", v), "n/a");  // no sample yet
    PixelSample s;
    s.covered = true;
    s.lighting = {0.017f, 0.5f, 1.0f, 1.0f};
    s.position = {1.0f, 0.0f, 2.0f, 1.0f};
    s.reconstructedPosition = {1.0f, 0.0f, 2.5f};
    v.sample = s;
    EXPECT_EQ(substituteLessonText("{pixel.lit} {pixel.error}", v), "(0.017, 0.5, 1) 0.5");
    EXPECT_EQ(unknownPlaceholder("a {light.kq} b {nope} c"), std::optional<std::string>("{nope}"));
    EXPECT_EQ(unknownPlaceholder("open {light.kq"), std::optional<std::string>("{light.kq"));
    EXPECT_FALSE(unknownPlaceholder("plain text"));
    // The live frame: its size, and the light evaluations a full-screen pass costs.
    EXPECT_EQ(substituteLessonText("{frame.width}x{frame.height}", v),
              "n/a"
              "x"
              "n/a");
    v.frameSize = {641, 400};
    EXPECT_EQ(substituteLessonText("{frame.width}\u00d7{frame.height}: {frame.evaluations}", v),
              "641\u00d7400: " + std::to_string(641 * 400 * 7));
    EXPECT_EQ(substituteLessonText("{frame.gbuffer_mb}", v), "9.23");  // 36 bytes x 641 x 400
}

TEST(LessonModel, ApplyingAStepAndLeavingRestoresTheEditor) {
    EditorState state;
    state.lights = makeDefaultLights(3);
    state.pipeline.shininess = 50.0f;
    state.lightsPanel.selected = 1;
    state.inspector.pixel = glm::ivec2(7, 9);
    LessonSnapshot const before = captureLessonSnapshot(state);
    LessonStep const step = parseLesson(minimalLesson().dump(), "demo.json").lesson->steps[0];
    applyLessonSnapshot(step.state, state, {640, 360});
    EXPECT_EQ(state.lights, step.state.lights);
    EXPECT_EQ(state.pipeline.cull, CullMode::Back);
    EXPECT_EQ(state.lightsPanel.selected, 2);
    EXPECT_EQ(state.gbuffer.activeViewer, int(ViewerKind::Depth));
    EXPECT_TRUE(state.inspector.locked);
    EXPECT_EQ(state.inspector.pixel, std::optional<glm::ivec2>(glm::ivec2(160, 270)));  // 0.25 x 640, 0.75 x 360
    applyLessonSnapshot(before, state, {640, 360});
    EXPECT_EQ(state.lights, before.lights);
    EXPECT_EQ(state.pipeline, before.pipeline);
    EXPECT_EQ(state.lightsPanel.selected, 1);
    EXPECT_FALSE(state.inspector.locked);
    EXPECT_EQ(state.inspector.pixel, std::optional<glm::ivec2>(glm::ivec2(7, 9)));
    EXPECT_EQ(lessonPixel({1.0f, 1.0f}, {640, 360}), glm::ivec2(639, 359));  // clamped into the frame
}

TEST(LessonModel, UndoKnowsEachLessonStepAsOneEntry) {
    UndoStack undo;
    UndoSnapshot a{makeDefaultLights(2), {}};
    undo.reset(a);
    UndoSnapshot b = a, c = a;
    b.pipeline.cull = CullMode::Back;
    c.pipeline.cull = CullMode::None;
    // Two pipeline edits within the merge window would be one step; committed steps are not.
    EXPECT_TRUE(undo.commit(b, 0.0));
    EXPECT_TRUE(undo.commit(c, 0.1));
    EXPECT_EQ(undo.undoSteps(), 2u);
    // An ordinary edit right after a committed step is a step of its own too.
    UndoSnapshot d = c;
    d.pipeline.cull = CullMode::Flip;
    EXPECT_TRUE(undo.observe(d, false, 0.2));
    EXPECT_EQ(undo.undoSteps(), 3u);
    EXPECT_FALSE(undo.commit(d, 0.3));  // nothing changed: no entry
    auto const back = undo.undo(d, 0.4);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->pipeline.cull, CullMode::None);
    EXPECT_EQ(undo.undo(*back, 0.5)->pipeline.cull, CullMode::Back);
}

TEST(LessonFile, AStepOpensTheAbSplitAndLeavingClosesIt) {
    json j = minimalLesson();
    j["steps"][0]["ab"] = {{"view", "diff"}, {"b", {{"cull", "front"}, {"shininess", 64}, {"light_cubes", false}}}};
    LessonLoad const l = parseLesson(j.dump(), "demo.json");
    ASSERT_TRUE(l.lesson) << l.error;
    auto const& ab = l.lesson->steps[0].state.ab;
    ASSERT_TRUE(ab);
    EXPECT_EQ(ab->view, AbView::Diff);
    EXPECT_EQ(ab->b.cull, CullMode::Front);
    EXPECT_EQ(ab->b.shininess, 64.0f);
    EXPECT_FALSE(ab->b.lightCubes);
    EXPECT_EQ(std::count(ab->overrides.begin(), ab->overrides.end(), true), 3);

    // Applied, the editor's A/B is on with B = the step's pipeline with those three changed.
    EditorState state;
    LessonSnapshot const before = captureLessonSnapshot(state);
    EXPECT_FALSE(before.ab);
    applyLessonSnapshot(l.lesson->steps[0].state, state, {640, 360});
    ASSERT_TRUE(state.ab.enabled);
    PipelineSettings const b = sideB(state.ab, state.pipeline);
    EXPECT_EQ(b.cull, CullMode::Front);
    EXPECT_EQ(b.mode, LightingMode::Volumes);
    EXPECT_EQ(state.pipeline.cull, CullMode::Back);
    EXPECT_EQ(describeAb(state.pipeline, b).find("cull"), 0u);
    // Leaving (the snapshot from before) turns it off again.
    applyLessonSnapshot(before, state, {640, 360});
    EXPECT_FALSE(state.ab.enabled);

    // Saved and read back, the step keeps its comparison.
    LessonLoad const again = parseLesson(lessonToJson(*l.lesson), "again.json");
    ASSERT_TRUE(again.lesson) << again.error;
    ASSERT_TRUE(again.lesson->steps[0].state.ab);
    EXPECT_EQ(again.lesson->steps[0].state.ab->b.cull, CullMode::Front);
    EXPECT_EQ(again.lesson->steps[0].state.ab->overrides, ab->overrides);
}
