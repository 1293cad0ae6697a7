#include "lesson_check.h"

#include "core/pipeline_settings.h"
#include "gl/caps.h"
#include "lesson_render.h"
#include "renderer.h"
#include "scene/default_scene.h"
#include "session/lesson_file.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdio>
#include <memory>
#include <sstream>
#include <vector>

namespace gbl {

namespace {

// The steps `spec` names: every step with a claim for "all", else a comma-separated list of ID:STEP.
std::vector<ui::LessonRef> stepsOf(ui::LessonLibrary const& lib, std::string const& spec, std::string* error) {
    std::vector<ui::LessonRef> refs;
    if (spec == "all") {
        for (std::size_t l = 0; l < lib.lessons.size(); ++l)
            for (std::size_t s = 0; s < lib.lessons[l].steps.size(); ++s)
                if (lib.lessons[l].steps[s].claim) refs.push_back({int(l), int(s), {}});
        return refs;
    }
    std::stringstream items(spec);
    for (std::string item; std::getline(items, item, ',');) {
        ui::LessonRef const ref = ui::findLessonStep(lib, item);
        if (ref.lesson < 0) {
            *error = "check-lessons: " + ref.error;
            return {};
        }
        refs.push_back(ref);
    }
    return refs;
}

}  // namespace

int checkLessonsInBrowser(std::string const& spec) {
    ui::LessonLibrary const lib = ui::loadLessonDir(ui::defaultLessonDir());
    if (!lib.errors.empty()) {
        std::fprintf(stderr, "lesson-check: %s\n", lib.errors.front().c_str());
        return 2;
    }
    std::string error;
    std::vector<ui::LessonRef> const refs = stepsOf(lib, spec, &error);
    if (!error.empty() || refs.empty()) {
        std::fprintf(stderr, "lesson-check: %s\n", error.empty() ? "no step to check" : error.c_str());
        return 2;
    }
    if (!glfwInit()) return 1;
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    GLFWwindow* window = glfwCreateWindow(640, 400, "gbuffer-lab lesson check", nullptr, nullptr);
    if (!window) {
        std::fprintf(stderr, "lesson-check: no WebGL2 context\n");
        return 1;
    }
    glfwMakeContextCurrent(window);
    Renderer renderer(detectGlCaps(), 640, 400);
    int hold = 0, fail = 0, skipped = 0;
    for (ui::LessonRef const& ref : refs) {
        ui::Lesson const& lesson = lib.lessons[std::size_t(ref.lesson)];
        ui::LessonStep const& step = lesson.steps[std::size_t(ref.step)];
        std::string const name = lesson.id + ":" + std::to_string(ref.step + 1);
        auto skip = [&](std::string const& why) {
            std::printf("lesson-check %s skipped: %s\n", name.c_str(), why.c_str());
            ++skipped;
        };
        if (!step.claim) {
            skip("the step has no claim");
            continue;
        }
        if (auto why = renderer.modeUnavailable(step.state.pipeline.mode)) {
            skip(*why);
            continue;
        }
        if (!lesson.scenePath.empty()) {
            skip("the lesson's glTF scene is not among the browser build's files");
            continue;
        }
        renderer.resizeTargets(lesson.width, lesson.height);
        if (auto err = renderer.setScene(makeDefaultScene({step.defaultSceneLights}))) {
            std::printf("lesson-check %s FAILS: the scene: %s\n", name.c_str(), err->c_str());
            ++fail;
            continue;
        }
        LessonStepFrame const frame = renderLessonStep(renderer, step);
        bool const holds = frame.claim && frame.claim->holds;
        std::printf("lesson-check %s %s: %s\n", name.c_str(), holds ? "holds" : "FAILS",
                    frame.claim ? frame.claim->detail.c_str() : "no result");
        ++(holds ? hold : fail);
    }
    std::printf("lesson-check: %d hold, %d fail, %d skipped\n", hold, fail, skipped);
    glfwDestroyWindow(window);
    return fail == 0 ? 0 : 1;
}

}  // namespace gbl
