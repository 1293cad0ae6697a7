// Lesson files on the CPU: a valid lesson reads with the session code's rules, broken ones give
// one message naming the field; placeholders, step references, saving a step, applying and
// leaving a lesson, and undo's one entry per step.
#include "session/lesson_file.h"
#include "core/light_math.h"
#include "model/lesson_claims.h"
#include "model/lesson_state.h"
#include "model/lesson_text.h"
#include "model/undo.h"
#include "run_command.h"
#include "scene/default_scene.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string_view>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <regex>

#include <stdlib.h>

using namespace gbl;
using namespace gbl::ui;
using nlohmann::json;

namespace {

// A shipped step by "ID:STEP" (the shipped library loaded once); a broken library or a missing
// step fails the test that asks, with the reason.
LessonStep const& shippedStep(std::string_view name) {
    static LessonLibrary const lib = loadLessonDir(defaultLessonDir());
    if (!lib.errors.empty()) throw std::runtime_error(lib.errors.front());
    LessonRef const ref = findLessonStep(lib, name);
    if (ref.lesson < 0) throw std::runtime_error(ref.error);
    return lib.lessons[std::size_t(ref.lesson)].steps[std::size_t(ref.step)];
}

json minimal() {
    return json::parse(R"({
      "format": "gbuffer-lab-lesson", "version": 2, "id": "demo", "title": "Demo",
      "setup": {"pipeline": {"mode": "volumes"}},
      "steps": [{"title": "One", "look": "look here", "equation": "r = {light.radius}", "question": "why?",
                 "answer": "because r = {light.radius}",
                 "scene": {"lights": 4}, "selected_light": 2, "viewer": "depth", "pixel": [0.25, 0.75],
                 "pipeline": {"cull": "back", "volume_scale": 0.5},
                 "camera": {"position": [0, 4, 8], "look_at": [0, 0, 0]},
                 "claim": {"kind": "loses_light", "light": 1, "reference": {"cull": "front"}}}]
    })");
}

std::string errorOf(json const& j) {
    LessonLoad const l = parseLesson(j.dump(), "demo.json");
    EXPECT_FALSE(l.lesson) << "parsed although broken";
    return l.error;
}

TEST(LessonFile, AValidLessonReadsEveryField) {
    LessonLoad const l = parseLesson(minimal().dump(), "demo.json");
    ASSERT_TRUE(l.lesson) << l.error;
    ASSERT_EQ(l.lesson->steps.size(), 1u);
    LessonStep const& s = l.lesson->steps[0];
    EXPECT_EQ(s.state.pipeline.mode, LightingMode::Volumes);  // from the setup
    EXPECT_EQ(s.state.pipeline.cull, CullMode::Back);         // from the step
    EXPECT_EQ(s.state.pipeline.volumeScale, 0.5f);
    EXPECT_EQ(s.state.lights, makeDefaultLights(4));
    EXPECT_EQ(s.defaultSceneLights, 4);
    EXPECT_EQ(s.state.selectedLight, 2);
    EXPECT_EQ(s.state.activeViewer, int(ViewerKind::Depth));
    ASSERT_TRUE(s.state.pixel);
    EXPECT_EQ(*s.state.pixel, glm::vec2(0.25f, 0.75f));
    // look_at: the camera faces the origin from (0, 4, 8).
    glm::vec3 const want = glm::normalize(glm::vec3(0, -4, -8));
    EXPECT_NEAR(glm::dot(s.state.camera.forward(), want), 1.0f, 1e-5f);
    ASSERT_TRUE(s.claim);
    EXPECT_EQ(s.claim->kind, ClaimKind::LosesLight);
    EXPECT_EQ(s.claim->light, 1);
    ASSERT_TRUE(s.claim->reference);
    EXPECT_EQ(s.claim->reference->cull, CullMode::Front);
    EXPECT_EQ(s.claim->reference->mode, LightingMode::Volumes);  // the step's pipeline, one setting changed
    EXPECT_EQ(s.claim->reference->volumeScale, 0.5f);
}

TEST(LessonFile, BrokenFilesNameTheField) {
    EXPECT_NE(parseLesson("{\"format\": ", "bad.json").error.find("bad.json: not valid JSON"), std::string::npos);
    struct Case {
        std::function<void(json&)> breakIt;
        std::string expect;
    };
    std::vector<Case> const cases{
        {[](json& j) { j["version"] = 3; }, "demo.json: version 3 is not supported"},
        {[](json& j) { j["steps"][0]["claim"]["reached"] = 1; },
         "demo.json: steps[0].claim.reached is not a field of a loses_light claim"},
        {[](json& j) { j["steps"][0]["claim"]["bound"] = 0.1; },  // same_image's, not loses_light's
         "demo.json: steps[0].claim.bound is not a field of a loses_light claim"},
        {[](json& j) {
             j["steps"][0]["claim"] = {{"kind", "matches_cpu"}, {"reached", 5}};
         },
         "demo.json: steps[0].claim.reached must be a whole number from 0 to 4 (got 5)"},
        {[](json& j) { j["version"] = 1; },
         "demo.json: version 1 is not supported; this program reads lesson version 2 (version 2 adds an \"answer\""},
        {[](json& j) { j["steps"][0].erase("answer"); },
         "demo.json: steps[0].answer is missing: step \"One\" of lesson demo asks a question and every question "
         "needs an answer"},
        {[](json& j) { j["steps"][0]["answer"] = " "; }, "demo.json: steps[0].answer must not be empty"},
        {[](json& j) { j["steps"][0]["answer"] = "{light.colour}"; },
         "demo.json: steps[0].answer uses the unknown placeholder {light.colour}"},
        {[](json& j) { j["format"] = "gbuffer-lab-session"; }, "demo.json: format must be \"gbuffer-lab-lesson\""},
        {[](json& j) { j["steps"][0]["pipeline"]["cull"] = "sideways"; },
         "demo.json: steps[0].pipeline.cull must be one of back, front, none, flip or stencil (got \"sideways\")"},
        {[](json& j) { j["setup"]["pipeline"]["mode"] = "magic"; }, "demo.json: setup.pipeline.mode must be one of"},
        {[](json& j) { j["steps"][0].erase("question"); }, "demo.json: steps[0].question is missing"},
        {[](json& j) { j["steps"][0]["look"] = "  "; }, "demo.json: steps[0].look must not be empty"},
        {[](json& j) { j.erase("title"); }, "demo.json: title is missing"},
        {[](json& j) { j["steps"][0]["equation"] = "{light.colour}"; },
         "demo.json: steps[0].equation uses the unknown placeholder {light.colour}"},
        {[](json& j) { j["steps"][0]["colour"] = 1; }, "demo.json: steps[0].colour is not a known field"},
        {[](json& j) { j["steps"][0]["claim"]["kind"] = "looks_nice"; },
         "demo.json: steps[0].claim.kind must be one of"},
        {[](json& j) { j["steps"][0]["claim"]["reference"]["cull"] = 3; },
         "demo.json: steps[0].claim.reference.cull must be one of"},
        {[](json& j) { j["steps"][0]["claim"]["light"] = 9; },
         "demo.json: steps[0].claim.light must be a whole number from 0 to 3"},
        {[](json& j) { j["steps"][0].erase("pixel"); },
         "demo.json: steps[0].claim.kind is a claim about the step's pixel"},
        {[](json& j) { j["steps"][0]["selected_light"] = 4; },
         "demo.json: steps[0].selected_light must be a whole number from -1 to 3"},
        {[](json& j) { j["steps"][0]["camera"]["fov_y_degrees"] = 0; },
         "demo.json: steps[0].camera.fov_y_degrees must be between 1 and 179"},
        {[](json& j) {
             j["steps"][0]["lights"] = json::array({{{"position", {0, 1, 0}}}});
         },
         "demo.json: steps[0].lights[0].color is missing"},
        {[](json& j) { j["steps"][0]["viewer"] = "stencil"; }, "demo.json: steps[0].viewer must be one of"},
        {[](json& j) { j["steps"] = json::array(); }, "demo.json: steps must be an array of at least one step"},
        {[](json& j) { j["id"] = "Has Space"; }, "demo.json: id must be lower-case letters"},
        {[](json& j) { j["steps"][0]["pipeline"]["volume_scale"] = 0.0; },
         "demo.json: steps[0].pipeline.volume_scale must be between"},
        {[](json& j) { j["setup"]["scene"]["glass"] = 1; }, "demo.json: setup.scene.glass must be true or false"},
        {[](json& j) { j["steps"][0]["scene"]["glass"] = "yes"; },
         "demo.json: steps[0].scene.glass must be true or false"},
        {[](json& j) { j["steps"][0]["scene"]["panes"] = 3; }, "demo.json: steps[0].scene.panes is not a known field"},
        {[](json& j) {
             j["steps"][0]["predict"] = {{"prompt", "p"},
                                         {"choices", {"a", "b"}},
                                         {"correct", 0},
                                         {"explain", "e"},
                                         {"before", {{"scene", {{"glass", true}}}}}};
         },
         "demo.json: steps[0].predict.before.scene.glass cannot differ from the step's"},
    };
    for (auto const& c : cases) {
        json j = minimal();
        c.breakIt(j);
        std::string const e = errorOf(j);
        EXPECT_EQ(e.rfind(c.expect, 0), 0u) << "got: " << e << "\nwant: " << c.expect;
    }
}

// "scene": {"glass": true} (issue 47): in setup it holds for every step, a step may turn it off again,
// the step's scene is then "default+glass", and a lesson written back keeps it. No shipped lesson but
// transparency stands the panes, so no other frame changed.
TEST(LessonFile, AStepMayAskForTheGlassScene) {
    json j = minimal();
    j["setup"]["scene"]["glass"] = true;
    j["steps"].push_back(j["steps"][0]);
    j["steps"][1]["scene"]["glass"] = false;
    LessonLoad const l = parseLesson(j.dump(), "demo.json");
    ASSERT_TRUE(l.lesson) << l.error;
    EXPECT_TRUE(l.lesson->steps[0].defaultSceneGlass);
    EXPECT_EQ(l.lesson->steps[0].defaultSceneLights, 4);
    EXPECT_FALSE(l.lesson->steps[1].defaultSceneGlass);
    EXPECT_EQ(lessonStepScene(*l.lesson, 0), "default+glass");
    EXPECT_EQ(lessonStepScene(*l.lesson, 1), "default");
    LessonLoad const again = parseLesson(lessonToJson(*l.lesson), "again.json");
    ASSERT_TRUE(again.lesson) << again.error;
    EXPECT_TRUE(again.lesson->steps[0].defaultSceneGlass);
    EXPECT_FALSE(again.lesson->steps[1].defaultSceneGlass);

    LessonLibrary const lib = loadLessonDir(defaultLessonDir());
    int glassSteps = 0;
    for (Lesson const& shipped : lib.lessons)
        for (LessonStep const& s : shipped.steps) {
            EXPECT_EQ(s.defaultSceneGlass, shipped.id == "transparency") << shipped.id;
            glassSteps += s.defaultSceneGlass;
        }
    EXPECT_EQ(glassSteps, 3);
}

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
    json j = minimal();
    j["steps"][0]["claim"] = {
        {"kind", "same_image"}, {"reference", {{"blit", "off"}}}, {"bound", 0.0}, {"image", "hdr"}};
    std::string const e = errorOf(j);
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
    json j = minimal();
    j["steps"][0]["claim"] = {{"kind", "differs_from"},
                              {"reference", {{"blit", "off"}}},
                              {"bound", 0.0},
                              {"min_fraction", 0.2},
                              {"max_fraction", 0.1}};
    std::string const e = errorOf(j);
    EXPECT_EQ(e.rfind("demo.json: steps[0].claim.max_fraction must be greater than min_fraction", 0), 0u) << e;
}

// A claim's numbers are read through claimNumberFields(): a value past a field's range is refused
// with the table's range, and an optional field left out is the table's default (LessonClaim{}'s).
TEST(LessonFile, ClaimNumbersTakeTheirRangesAndDefaultsFromTheTable) {
    // A claim of a kind that takes each number, valid as it stands (the step of minimal() has a pixel
    // and four lights).
    json const reference = {{"cull", "front"}};
    std::map<std::string, json> const claims{
        {"tolerance", {{"kind", "loses_light"}, {"light", 1}, {"reference", reference}}},
        {"bound", {{"kind", "same_image"}, {"reference", reference}, {"bound", 0.5}}},
        {"at_least", {{"kind", "position_error_below"}, {"bound", 1e6}}},
        {"min_fraction", {{"kind", "fewer_lit_pixels"}, {"reference", reference}, {"min_fraction", 0.5}}},
        {"max_fraction", {{"kind", "differs_from"}, {"reference", reference}, {"bound", 0.0}, {"min_fraction", 0.0}}},
    };
    ASSERT_EQ(claims.size(), claimNumberFields().size());
    for (ClaimNumberField const& f : claimNumberFields()) {
        std::string const name(f.name);
        ASSERT_TRUE(claims.count(name)) << name << " has no claim in this test";
        json j = minimal();
        j["steps"][0]["claim"] = claims.at(name);
        LessonLoad const ok = parseLesson(j.dump(), "demo.json");
        ASSERT_TRUE(ok.lesson) << name << ": " << ok.error;
        ASSERT_TRUE(ok.lesson->steps[0].claim);
        LessonClaim const& claim = *ok.lesson->steps[0].claim;
        if (!j["steps"][0]["claim"].contains(name)) {
            EXPECT_EQ(claim.*f.member, f.defaultValue()) << name << " left out is not its default";
        }
        j["steps"][0]["claim"][name] = double(f.max) + 1.0;
        std::string const e = errorOf(j);
        std::string const want = "demo.json: steps[0].claim." + name + " must be a number from " + json(f.min).dump() +
                                 " to " + json(f.max).dump();
        EXPECT_EQ(e.rfind(want, 0), 0u) << e << "\nwanted: " << want;
    }
    // The defaults the shipped lessons rely on.
    EXPECT_EQ(findClaimNumberField("tolerance")->defaultValue(), 0.02f);
    EXPECT_EQ(findClaimNumberField("max_fraction")->defaultValue(), 1.0f);
    EXPECT_EQ(findClaimNumberField("at_least")->defaultValue(), 0.0f);
    EXPECT_FALSE(findClaimNumberField("light")) << "light's range is the step's light count, not the table's";
}

// An old lesson's "blit" (the depth copy's old name) reads as depth_copy wherever a lesson names
// settings: the step's pipeline over a setup that says depth_copy, a claim's reference, A/B's side B.
TEST(LessonFile, TheDepthCopysOldNameStillLoads) {
    json j = minimal();
    j["setup"]["pipeline"]["depth_copy"] = "shader";
    j["steps"][0]["pipeline"]["blit"] = "off";
    j["steps"][0]["claim"] = {{"kind", "same_image"}, {"reference", {{"blit", "blit"}}}, {"bound", 0.5}};
    j["steps"][0]["ab"] = {{"view", "split"}, {"b", {{"blit", "shader"}}}};
    LessonLoad const l = parseLesson(j.dump(), "demo.json");
    ASSERT_TRUE(l.lesson) << l.error;
    LessonStep const& step = l.lesson->steps[0];
    EXPECT_EQ(step.state.pipeline.depthCopy, DepthCopy::Off);  // the step's old key over the setup's new one
    ASSERT_TRUE(step.claim && step.claim->reference);
    EXPECT_EQ(step.claim->reference->depthCopy, DepthCopy::Blit);
    ASSERT_TRUE(step.state.ab);
    EXPECT_EQ(step.state.ab->b.depthCopy, DepthCopy::Shader);
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
    json j = minimal();
    j["steps"][0]["claim"] = {{"kind", "fewer_evaluations"}, {"reference", {{"cull", "front"}}}, {"min_fraction", 0.1}};
    std::string e = errorOf(j);
    EXPECT_EQ(e.rfind("demo.json: steps[0].claim.kind needs pipeline.view \"heatmap\"", 0), 0u) << e;
    j["steps"][0]["pipeline"]["view"] = "heatmap";
    j["steps"][0]["claim"]["max_fraction"] = 0.05;
    e = errorOf(j);
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

TEST(LessonFile, StepReferences) {
    LessonLibrary lib;
    lib.lessons.push_back(*parseLesson(minimal().dump(), "demo.json").lesson);
    EXPECT_EQ(findLessonStep(lib, "demo").step, 0);
    EXPECT_EQ(findLessonStep(lib, "demo:1").lesson, 0);
    EXPECT_NE(findLessonStep(lib, "demo:2").error.find("has steps 1 to 1"), std::string::npos);
    EXPECT_NE(findLessonStep(lib, "demo:x").error.find("not \"x\""), std::string::npos);
    EXPECT_NE(findLessonStep(lib, "other").error.find("(lessons: demo)"), std::string::npos);
}

TEST(LessonFile, ASavedStepReadsBackAsTheSameState) {
    std::string const dir = test::freshTempDir("lesson_save");
    std::string const path = dir + "/My Lesson.json";
    LessonStep step = parseLesson(minimal().dump(), "demo.json").lesson->steps[0];
    step.claim.reset();  // saved steps carry no claim: a teacher writes that by hand
    step.state.lights[1].kq = 0.123f;
    step.state.pipeline.shininess = 12.5f;
    ASSERT_FALSE(appendLessonStep(path, step));
    ASSERT_FALSE(appendLessonStep(path, step));  // appends to the file now present
    LessonLoad const back = loadLesson(path);
    ASSERT_TRUE(back.lesson) << back.error;
    EXPECT_EQ(back.lesson->id, "my_lesson");
    ASSERT_EQ(back.lesson->steps.size(), 2u);
    LessonStep const& s = back.lesson->steps[1];
    EXPECT_EQ(s.state.lights, step.state.lights);
    EXPECT_EQ(s.state.pipeline, step.state.pipeline);
    EXPECT_EQ(s.state.camera.position, step.state.camera.position);
    EXPECT_EQ(s.state.camera.yawDegrees, step.state.camera.yawDegrees);
    EXPECT_EQ(s.state.selectedLight, 2);
    EXPECT_EQ(s.state.activeViewer, int(ViewerKind::Depth));
    EXPECT_EQ(s.text.equation, "r = {light.radius}");
    // A file that is not a lesson is not overwritten.
    std::ofstream(dir + "/notes.json") << "{}";
    auto const err = appendLessonStep(dir + "/notes.json", step);
    ASSERT_TRUE(err);
    EXPECT_NE(err->find("notes.json: format is missing"), std::string::npos) << *err;
}

// --- lessons on a glTF scene ------------------------------------------------------------------

// A lesson on the test data's triangle: its own lights and camera, as a glTF lesson must have.
json onScene(std::string const& scene) {
    json j = minimal();
    j["scene"] = scene;
    j["setup"]["lights"] = json::parse(R"([{"position": [0, 1, 2], "color": [1, 1, 1], "intensity": 1,
                                             "kc": 1, "kl": 0.35, "kq": 0.44, "threshold": 0.01953125}])");
    j["setup"]["camera"] = json::parse(R"({"position": [0, 0, 3], "look_at": [0, 0, 0]})");
    j["steps"][0].erase("claim");  // its light 1 is the default scene's
    j["steps"][0]["selected_light"] = 0;
    return j;
}

// Copies the test data's triangle (its .gltf and .bin) into `dir`.
void copyTriangle(std::string const& dir) {
    namespace fs = std::filesystem;
    for (char const* f : {"triangle.gltf", "triangle.bin"})
        fs::copy_file(fs::path(test::dataDir()) / "gltf" / f, fs::path(dir) / f, fs::copy_options::overwrite_existing);
}

// Sets an environment variable for one scope and puts the old value back.
struct ScopedEnv {
    std::string name;
    std::optional<std::string> old;
    ScopedEnv(std::string n, std::string const& value) : name(std::move(n)) {
        if (char const* v = std::getenv(name.c_str())) old = v;
        ::setenv(name.c_str(), value.c_str(), 1);
    }
    ~ScopedEnv() {
        if (old)
            ::setenv(name.c_str(), old->c_str(), 1);
        else
            ::unsetenv(name.c_str());
    }
};

TEST(LessonScene, ASceneIsFoundBesideTheLessonThenInTheSharedModels) {
    namespace fs = std::filesystem;
    std::string const dir = test::freshTempDir("lesson_scene");
    copyTriangle(dir);
    std::ofstream(dir + "/tri.json") << onScene("triangle.gltf").dump();
    LessonLoad const beside = loadLesson(dir + "/tri.json");
    ASSERT_TRUE(beside.lesson) << beside.error;
    EXPECT_EQ(beside.lesson->scene, "triangle.gltf");
    EXPECT_TRUE(fs::equivalent(beside.lesson->scenePath, dir + "/triangle.gltf")) << beside.lesson->scenePath;
    EXPECT_EQ(beside.lesson->steps[0].state.lights.size(), 1u);  // the setup's, not the default scene's 32

    // Not beside the lesson: the shared models folder ($GBL_SHARED_GLTF_DIR here) is next.
    std::string const models = test::freshTempDir("lesson_scene_models");
    fs::create_directories(models + "/Tri");
    copyTriangle(models + "/Tri");
    std::string const lessons = test::freshTempDir("lesson_scene_lessons");
    std::ofstream(lessons + "/tri.json") << onScene("Tri/triangle.gltf").dump();
    {
        ScopedEnv env("GBL_SHARED_GLTF_DIR", models);
        EXPECT_EQ(sharedModelsDir(), models);
        LessonLoad const shared = loadLesson(lessons + "/tri.json");
        ASSERT_TRUE(shared.lesson) << shared.error;
        EXPECT_TRUE(fs::equivalent(shared.lesson->scenePath, models + "/Tri/triangle.gltf"));
    }
    // Without it, the lesson is refused in one sentence naming the field and both places looked in,
    // and the other lessons of the folder still load.
    {
        ScopedEnv env("GBL_SHARED_GLTF_DIR", dir + "/no_models");
        std::ofstream(lessons + "/a.json") << minimal().dump();
        LessonLibrary const lib = loadLessonDir(lessons);
        ASSERT_EQ(lib.lessons.size(), 1u);
        EXPECT_EQ(lib.lessons[0].id, "demo");
        ASSERT_EQ(lib.errors.size(), 1u);
        std::string const want = lessons + "/tri.json: scene \"Tri/triangle.gltf\" is not a file: neither " + lessons +
                                 "/Tri/triangle.gltf nor " + dir + "/no_models/Tri/triangle.gltf exists";
        EXPECT_NE(lib.errors[0].find(want), std::string::npos) << lib.errors[0];
    }
}

TEST(LessonScene, TheSharedModelsFolderIsTheDefault) {
    std::string const box = test::sharedGltfDir() + "/Box/Box.gltf";
    if (!std::filesystem::exists(box)) GTEST_SKIP() << "needs the shared models: " << box << " is absent";
    if (std::getenv("GBL_SHARED_GLTF_DIR")) GTEST_SKIP() << "GBL_SHARED_GLTF_DIR is set: the default is not used";
    LessonLoad const l = parseLesson(onScene("Box/Box.gltf").dump(), test::freshTempDir("lesson_box") + "/box.json");
    ASSERT_TRUE(l.lesson) << l.error;
    EXPECT_TRUE(std::filesystem::equivalent(l.lesson->scenePath, box)) << l.lesson->scenePath;
}

TEST(LessonScene, BadScenesNameTheField) {
    std::string const dir = test::freshTempDir("lesson_scene_bad");
    copyTriangle(dir);
    std::string const label = dir + "/x.json";
    auto error = [&](json const& j) {
        LessonLoad const l = parseLesson(j.dump(), label);
        EXPECT_FALSE(l.lesson) << "parsed although broken";
        return l.error;
    };
    EXPECT_EQ(error(onScene("")), label + ": scene must be the path of a glTF file (.gltf or .glb)");
    json number = onScene("x");
    number["scene"] = 3;
    EXPECT_EQ(error(number), label + ": scene must be the path of a glTF file (.gltf or .glb)");
    EXPECT_EQ(error(onScene("triangle.bin")), label + ": scene must name a .gltf or .glb file (got \"triangle.bin\")");
    // The default scene's lights and camera do not fit another scene: a glTF lesson names its own.
    json noLights = onScene("triangle.gltf");
    noLights["setup"].erase("lights");
    EXPECT_NE(error(noLights).find(label + ": steps[0].lights is missing: a lesson on a glTF scene"),
              std::string::npos);
    json noCamera = onScene("triangle.gltf");
    noCamera["setup"].erase("camera");
    noCamera["steps"][0].erase("camera");
    EXPECT_NE(error(noCamera).find(label + ": steps[0].camera.position is missing: a lesson on a glTF scene"),
              std::string::npos);
}

TEST(LessonScene, ASavedStepKeepsItsScene) {
    namespace fs = std::filesystem;
    std::string const dir = test::freshTempDir("lesson_scene_save");
    copyTriangle(dir);
    std::string const scene = dir + "/triangle.gltf";
    LessonStep const step = parseLesson(minimal().dump(), "demo.json").lesson->steps[0];
    std::string const path = dir + "/saved.json";
    ASSERT_FALSE(appendLessonStep(path, step, scene));
    ASSERT_FALSE(appendLessonStep(path, step, scene));
    LessonLoad const back = loadLesson(path);
    ASSERT_TRUE(back.lesson) << back.error;
    EXPECT_EQ(back.lesson->steps.size(), 2u);
    EXPECT_TRUE(fs::equivalent(back.lesson->scenePath, scene));
    // A step set up on another scene is not added to it, and the file stays as it was.
    auto const other = appendLessonStep(path, step);
    ASSERT_TRUE(other);
    EXPECT_NE(other->find("and the editor shows the default scene"), std::string::npos) << *other;
    EXPECT_EQ(loadLesson(path).lesson->steps.size(), 2u);
}

TEST(LessonFile, ABrokenFileInTheFolderIsReportedAndTheOthersLoad) {
    std::string const dir = test::freshTempDir("lesson_dir");
    std::ofstream(dir + "/a.json") << minimal().dump();
    json bad = minimal();
    bad["steps"][0]["pipeline"]["blit"] = "copy";
    std::ofstream(dir + "/b.json") << bad.dump();
    std::ofstream(dir + "/c.json") << minimal().dump();  // the same id again
    json noAnswer = minimal();
    noAnswer["id"] = "other";
    noAnswer["steps"][0].erase("answer");
    std::ofstream(dir + "/d.json") << noAnswer.dump();
    LessonLibrary const lib = loadLessonDir(dir);
    ASSERT_EQ(lib.lessons.size(), 1u);
    ASSERT_EQ(lib.errors.size(), 3u);
    EXPECT_NE(lib.errors[2].find("d.json: steps[0].answer is missing: step \"One\" of lesson other"), std::string::npos)
        << lib.errors[2];
    EXPECT_NE(lib.errors[0].find("b.json: steps[0].pipeline.blit must be one of blit, shader or off"),
              std::string::npos)
        << lib.errors[0];
    EXPECT_NE(lib.errors[1].find("c.json: id \"demo\" is already used"), std::string::npos) << lib.errors[1];
}

TEST(LessonModel, ApplyingAStepAndLeavingRestoresTheEditor) {
    EditorState state;
    state.lights = makeDefaultLights(3);
    state.pipeline.shininess = 50.0f;
    state.lightsPanel.selected = 1;
    state.inspector.pixel = glm::ivec2(7, 9);
    LessonSnapshot const before = captureLessonSnapshot(state);
    LessonStep const step = parseLesson(minimal().dump(), "demo.json").lesson->steps[0];
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

}  // namespace

TEST(LessonFile, AStepOpensTheAbSplitAndLeavingClosesIt) {
    json j = minimal();
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

TEST(LessonFile, ABadAbFieldIsNamed) {
    json j = minimal();
    j["steps"][0]["ab"] = {{"b", {{"zebra", 1}}}};
    EXPECT_NE(errorOf(j).find("steps[0].ab.b.zebra"), std::string::npos) << errorOf(j);
    j["steps"][0]["ab"] = {{"b", {{"cull", "sideways"}}}};
    EXPECT_NE(errorOf(j).find("steps[0].ab.b.cull"), std::string::npos) << errorOf(j);
    j["steps"][0]["ab"] = {{"view", "both"}, {"b", {{"cull", "front"}}}};
    EXPECT_NE(errorOf(j).find("steps[0].ab.view"), std::string::npos) << errorOf(j);
    j["steps"][0]["ab"] = {{"b", json::object()}};
    EXPECT_NE(errorOf(j).find("steps[0].ab.b"), std::string::npos) << errorOf(j);
}
