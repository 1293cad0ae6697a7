// A lesson step that opens the viewport's light-by-light scrubber ("light_by_light"): read, applied
// to the editor, written back, and refused with the field named when wrong (issue 27).
#include "model/editor_state.h"
#include "model/lesson_state.h"
#include "session/lesson_file.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace gbl;
using namespace gbl::ui;
using nlohmann::json;

namespace {

json demo() {
    return json::parse(R"({
      "format": "gbuffer-lab-lesson", "version": 2, "id": "demo", "title": "Demo",
      "steps": [{"title": "One", "look": "look", "equation": "r = {light.radius}", "question": "why?",
                 "answer": "because", "scene": {"lights": 8}, "selected_light": 6,
                 "light_by_light": {"light": 6, "only": true}},
                {"title": "Two", "look": "look", "equation": "e", "question": "why?", "answer": "because"}]
    })");
}

std::string errorOf(json const& j) {
    LessonLoad const l = parseLesson(j.dump(), "demo.json");
    EXPECT_FALSE(l.lesson) << "parsed although broken";
    return l.error;
}

TEST(LessonLightByLight, AStepOpensTheScrubberAtItsLightAndTheNextClosesIt) {
    LessonLoad const l = parseLesson(demo().dump(), "demo.json");
    ASSERT_TRUE(l.lesson) << l.error;
    auto const& lbl = l.lesson->steps[0].state.lightByLight;
    ASSERT_TRUE(lbl);
    EXPECT_EQ(lbl->light, 6);
    EXPECT_TRUE(lbl->only);
    EXPECT_FALSE(l.lesson->steps[1].state.lightByLight);

    EditorState state;
    applyLessonSnapshot(l.lesson->steps[0].state, state, {640, 360});
    EXPECT_TRUE(state.accumulate.enabled);
    EXPECT_EQ(state.accumulate.count, 7);  // the scrubber counts lights from 1: k = light + 1
    EXPECT_TRUE(state.accumulate.contribution);
    applyLessonSnapshot(l.lesson->steps[1].state, state, {640, 360});
    EXPECT_FALSE(state.accumulate.enabled);

    // Saved and read back, the step keeps its scrubber.
    LessonLoad const again = parseLesson(lessonToJson(*l.lesson), "again.json");
    ASSERT_TRUE(again.lesson) << again.error;
    ASSERT_TRUE(again.lesson->steps[0].state.lightByLight);
    EXPECT_EQ(again.lesson->steps[0].state.lightByLight->light, 6);
    EXPECT_TRUE(again.lesson->steps[0].state.lightByLight->only);
}

TEST(LessonLightByLight, BadFieldsAreNamed) {
    json j = demo();
    j["steps"][0]["light_by_light"] = {{"light", 8}};  // 8 lights: 0..7
    EXPECT_NE(errorOf(j).find("steps[0].light_by_light.light"), std::string::npos) << errorOf(j);
    j["steps"][0]["light_by_light"] = {{"only", true}};
    EXPECT_NE(errorOf(j).find("steps[0].light_by_light.light"), std::string::npos) << errorOf(j);
    j["steps"][0]["light_by_light"] = {{"light", 1}, {"only", "yes"}};
    EXPECT_NE(errorOf(j).find("steps[0].light_by_light.only"), std::string::npos) << errorOf(j);
    j["steps"][0]["light_by_light"] = {{"light", 1}, {"k", 2}};
    EXPECT_NE(errorOf(j).find("steps[0].light_by_light.k"), std::string::npos) << errorOf(j);
}

// fullscreen_pass:3 asks the student to drag light 6's intensity: it shows that light's term alone.
TEST(LessonLightByLight, TheFullScreenPassTermStepShowsItsLightAlone) {
    LessonLoad const l = loadLesson(test::sourcePath("assets/lessons/03_fullscreen_pass.json"));
    ASSERT_TRUE(l.lesson) << l.error;
    ui::LessonStep const& step = l.lesson->steps[2];
    ASSERT_TRUE(step.state.lightByLight);
    EXPECT_EQ(step.state.lightByLight->light, step.state.selectedLight);
    EXPECT_TRUE(step.state.lightByLight->only);
}

}  // namespace
