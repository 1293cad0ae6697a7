// Lessons for the CPU tests of lesson files and steps (lesson_file_test, lesson_steps_test): a
// minimal valid lesson to break one field at a time, the message a broken one gives, and a shipped
// step by reference.
#pragma once

#include "session/lesson_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>
#include <string_view>

namespace gbl::test {

// One step with every field (a claim, a pixel, a camera, pipeline settings over the setup's), four
// lights of the default scene: a valid lesson "demo" as read from "demo.json".
inline nlohmann::json minimalLesson() {
    return nlohmann::json::parse(R"({
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

// The message of a lesson that must be refused (a test failure when it reads).
inline std::string lessonError(nlohmann::json const& j) {
    ui::LessonLoad const l = ui::parseLesson(j.dump(), "demo.json");
    EXPECT_FALSE(l.lesson) << "parsed although broken";
    return l.error;
}

// A shipped step by "ID:STEP" (the shipped library loaded once); a broken library or a missing
// step fails the test that asks, with the reason.
inline ui::LessonStep const& shippedStep(std::string_view name) {
    static ui::LessonLibrary const lib = ui::loadLessonDir(ui::defaultLessonDir());
    if (!lib.errors.empty()) throw std::runtime_error(lib.errors.front());
    ui::LessonRef const ref = ui::findLessonStep(lib, name);
    if (ref.lesson < 0) throw std::runtime_error(ref.error);
    return lib.lessons[std::size_t(ref.lesson)].steps[std::size_t(ref.step)];
}

}  // namespace gbl::test
