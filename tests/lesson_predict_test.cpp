// Predictions and the glossary on the CPU (issue 27): a step's "predict" reads (multiple choice or a
// number with a tolerance, and the state shown before the change), broken ones name the field, the
// right/wrong logic, saving keeps a prediction, and the glossary's terms are found in lesson text.
#include "model/lesson_state.h"
#include "run_command.h"
#include "session/glossary_file.h"
#include "session/lesson_file.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

using namespace gbl;
using namespace gbl::ui;
using nlohmann::json;

namespace {

json lesson() {
    return json::parse(R"({
      "format": "gbuffer-lab-lesson", "version": 2, "id": "p", "title": "P",
      "steps": [
        {"title": "Cull", "look": "l", "equation": "e", "question": "q?", "answer": "a.",
         "pipeline": {"mode": "volumes", "cull": "back"},
         "predict": {"prompt": "Which cull mode loses the light?", "choices": ["back", "front", "none"],
                     "correct": 0, "explain": "front faces are behind the camera",
                     "before": {"pipeline": {"cull": "front"}}}},
        {"title": "Radius", "look": "l", "equation": "e", "question": "q?", "answer": "a.",
         "lights": [{"position": [0, 1, 0], "color": [1, 1, 1], "intensity": 1, "threshold": 0.01953125, "kc": 1, "kl": 0.35, "kq": 1.8}],
         "predict": {"prompt": "New radius?", "number": 5.19, "tolerance": 0.4, "explain": "r = {light.radius}",
                     "before": {"lights": [{"position": [0, 1, 0], "color": [1, 1, 1], "intensity": 1, "threshold": 0.01953125, "kc": 1, "kl": 0.35,
                                            "kq": 0.44}]}}}]
    })");
}

TEST(LessonPredict, MultipleChoiceAndNumberRead) {
    LessonLoad const l = parseLesson(lesson().dump(), "p.json");
    ASSERT_TRUE(l.lesson) << l.error;
    ASSERT_TRUE(l.lesson->steps[0].predict);
    LessonPrediction const& mc = *l.lesson->steps[0].predict;
    EXPECT_EQ(mc.choices.size(), 3u);
    EXPECT_EQ(mc.correct, 0);
    ASSERT_TRUE(mc.before);
    EXPECT_EQ(mc.before->pipeline.cull, CullMode::Front);               // shown while predicting
    EXPECT_EQ(mc.before->pipeline.mode, LightingMode::Volumes);         // the rest is the step's
    EXPECT_EQ(l.lesson->steps[0].state.pipeline.cull, CullMode::Back);  // applied after
    LessonPrediction const& num = *l.lesson->steps[1].predict;
    EXPECT_TRUE(num.choices.empty());
    EXPECT_FLOAT_EQ(num.number, 5.19f);
    EXPECT_FLOAT_EQ(num.tolerance, 0.4f);
    ASSERT_TRUE(num.before);
    EXPECT_FLOAT_EQ(num.before->lights.at(0).kq, 0.44f);
    EXPECT_FLOAT_EQ(l.lesson->steps[1].state.lights.at(0).kq, 1.8f);
}

TEST(LessonPredict, RightAndWrong) {
    LessonLoad const l = parseLesson(lesson().dump(), "p.json");
    ASSERT_TRUE(l.lesson) << l.error;
    LessonPrediction const& mc = *l.lesson->steps[0].predict;
    EXPECT_TRUE(predictionRight(mc, 0, 0.0f));
    EXPECT_FALSE(predictionRight(mc, 1, 0.0f));
    EXPECT_FALSE(predictionRight(mc, -1, 0.0f));  // nothing picked
    LessonPrediction const& num = *l.lesson->steps[1].predict;
    EXPECT_TRUE(predictionRight(num, -1, 5.19f));
    EXPECT_TRUE(predictionRight(num, -1, 5.5f));  // within 0.4
    EXPECT_TRUE(predictionRight(num, -1, 4.8f));
    EXPECT_FALSE(predictionRight(num, -1, 5.6f));  // off by 0.41
    EXPECT_FALSE(predictionRight(num, -1, 10.29f));
    EXPECT_FALSE(predictionRight(num, -1, std::nanf("")));
}

TEST(LessonPredict, BrokenPredictionsNameTheField) {
    struct Case {
        std::function<void(json&)> breakIt;
        std::string expect;
    };
    std::vector<Case> const cases{
        {[](json& j) { j["steps"][0]["predict"].erase("prompt"); }, "p.json: steps[0].predict.prompt is missing"},
        {[](json& j) { j["steps"][0]["predict"].erase("explain"); }, "p.json: steps[0].predict.explain is missing"},
        {[](json& j) { j["steps"][0]["predict"]["correct"] = 3; },
         "p.json: steps[0].predict.correct must be a whole number from 0 to 2"},
        {[](json& j) { j["steps"][0]["predict"].erase("correct"); }, "p.json: steps[0].predict.correct is missing"},
        {[](json& j) { j["steps"][0]["predict"]["choices"] = json::array({"only"}); },
         "p.json: steps[0].predict.choices must be an array of 2 to 6 strings"},
        {[](json& j) { j["steps"][0]["predict"]["number"] = 1; },
         "p.json: steps[0].predict must have either choices (with correct) or number (with tolerance)"},
        {[](json& j) { j["steps"][1]["predict"].erase("tolerance"); }, "p.json: steps[1].predict.tolerance is missing"},
        {[](json& j) { j["steps"][0]["predict"]["before"]["pipeline"]["cull"] = "up"; },
         "p.json: steps[0].predict.before.pipeline.cull must be one of"},
        {[](json& j) {
             j["steps"][0]["predict"]["before"]["pixel"] = {0.5, 0.5};
         },
         "p.json: steps[0].predict.before.pixel is not a known field"},
        {[](json& j) { j["steps"][0]["predict"]["hint"] = "x"; }, "p.json: steps[0].predict.hint is not a known field"},
        {[](json& j) { j["steps"][0]["predict"]["explain"] = "{nope}"; },
         "p.json: steps[0].predict.explain uses the unknown placeholder {nope}"},
    };
    for (auto const& c : cases) {
        json j = lesson();
        c.breakIt(j);
        LessonLoad const l = parseLesson(j.dump(), "p.json");
        EXPECT_FALSE(l.lesson);
        EXPECT_EQ(l.error.rfind(c.expect, 0), 0u) << "got: " << l.error << "\nwant: " << c.expect;
    }
}

TEST(LessonPredict, ASavedStepKeepsItsPredictionAndAnswer) {
    std::string const path = test::freshTempDir("lesson_predict_save") + "/saved.json";
    Lesson const l = *parseLesson(lesson().dump(), "p.json").lesson;
    ASSERT_FALSE(appendLessonStep(path, l.steps[0]));
    ASSERT_FALSE(appendLessonStep(path, l.steps[1]));
    LessonLoad const back = loadLesson(path);
    ASSERT_TRUE(back.lesson) << back.error;
    EXPECT_EQ(back.lesson->steps[0].text.answer, "a.");
    ASSERT_TRUE(back.lesson->steps[0].predict && back.lesson->steps[1].predict);
    EXPECT_EQ(back.lesson->steps[0].predict->choices, l.steps[0].predict->choices);
    ASSERT_TRUE(back.lesson->steps[0].predict->before);
    EXPECT_EQ(back.lesson->steps[0].predict->before->pipeline.cull, CullMode::Front);
    EXPECT_FLOAT_EQ(back.lesson->steps[1].predict->number, 5.19f);
    EXPECT_FLOAT_EQ(back.lesson->steps[1].predict->before->lights.at(0).kq, 0.44f);
}

// The shipped lessons: at least three ask for a prediction; each one's right answer is right and
// its `before` differs from the step (the step really applies a change after the prediction).
TEST(LessonPredict, ShippedPredictions) {
    LessonLibrary const lib = loadLessonDir(defaultLessonDir());
    ASSERT_TRUE(lib.errors.empty()) << lib.errors.front();
    int lessonsWithPredictions = 0;
    for (Lesson const& l : lib.lessons) {
        bool any = false;
        for (LessonStep const& s : l.steps) {
            if (!s.predict) continue;
            any = true;
            LessonPrediction const& p = *s.predict;
            EXPECT_TRUE(predictionRight(p, p.correct, p.number)) << l.id;
            if (p.before) {
                EXPECT_TRUE(p.before->pipeline != s.state.pipeline || p.before->lights != s.state.lights) << l.id;
            }
        }
        lessonsWithPredictions += any;
    }
    EXPECT_GE(lessonsWithPredictions, 3);
}

TEST(Glossary, ReadsAndFindsTermsInText) {
    Glossary const g = parseGlossary(R"({"format": "gbuffer-lab-glossary", "version": 1, "terms": [
        {"term": "NDC", "aliases": ["normalized device coordinates"], "definition": "-1..1"},
        {"term": "tile", "aliases": ["tiles"], "definition": "16x16 pixels"},
        {"term": "G-buffer", "definition": "the attachments"}]})",
                                     "g.json");
    ASSERT_TRUE(g.error.empty()) << g.error;
    ASSERT_EQ(g.terms.size(), 3u);
    // In order of first mention, each once, whole words only, any case.
    EXPECT_EQ(glossaryTermsIn(g, "The g-buffer stores it; x_ndc uses NDC. Tiles, tile, tiled."),
              (std::vector<int>{2, 0, 1}));
    EXPECT_TRUE(glossaryTermsIn(g, "tiled lighting, x_ndc").empty());
    EXPECT_NE(parseGlossary(R"({"format": "gbuffer-lab-glossary", "version": 1, "terms": [{"term": "x"}]})", "g.json")
                  .error.find("g.json: terms[0].definition is missing"),
              std::string::npos);
    EXPECT_NE(parseGlossary("{", "g.json").error.find("g.json: not valid JSON"), std::string::npos);
}

TEST(Glossary, TheShippedGlossaryCoversTheLessonsTerms) {
    Glossary const g = loadGlossary(defaultGlossaryPath());
    ASSERT_TRUE(g.error.empty()) << g.error;
    for (std::string_view want : {"NDC", "window-space depth", "Kc, Kl, Kq", "stencil mark", "tile", "cluster",
                                  "G-buffer", "MRT", "light volume", "depth blit"})
        EXPECT_TRUE(std::any_of(g.terms.begin(), g.terms.end(), [&](GlossaryTerm const& t) { return t.term == want; }))
            << want;
    // Every shipped step's text names at least one glossary term, so "Terms:" is never empty.
    LessonLibrary const lib = loadLessonDir(defaultLessonDir());
    for (Lesson const& l : lib.lessons)
        for (std::size_t i = 0; i < l.steps.size(); ++i) {
            LessonText const& t = l.steps[i].text;
            EXPECT_FALSE(glossaryTermsIn(g, t.look + " " + t.equation + " " + t.question).empty())
                << l.id << ":" << i + 1;
        }
}

}  // namespace

TEST(LessonReturn, LeavingPutsBackTheToolsUsedDuringTheLesson) {
    gbl::ui::EditorState state;
    state.lights.resize(3);
    state.viewportTools.open = true;
    gbl::ui::LessonReturn const r = gbl::ui::captureLessonReturn(state);
    // What a student does during a lesson: tools closed, lit frame pinned and diffed, every light
    // listed, the scrubber on, A/B's threshold moved, the frame stopped after a pass.
    state.viewportTools.open = false;
    state.litPin.pinned = gbl::FloatImage{};
    state.litPin.showDiff = true;
    state.inspector.everyLight = true;
    state.accumulate.enabled = true;
    state.accumulate.count = 2;
    state.ab.threshold = 0.5f;
    state.frame.stopAfter = gbl::PassId::Geometry;
    state.lights.resize(1);
    gbl::ui::applyLessonReturn(r, state, {64, 64});
    EXPECT_TRUE(state.viewportTools.open);
    EXPECT_FALSE(state.litPin.pinned);
    EXPECT_FALSE(state.litPin.showDiff);
    EXPECT_FALSE(state.inspector.everyLight);
    EXPECT_FALSE(state.accumulate.enabled);
    EXPECT_EQ(state.ab.threshold, r.abThreshold);
    EXPECT_FALSE(state.frame.stopAfter);
    EXPECT_EQ(state.lights.size(), 3u);
}
