#include "lesson_check.h"

#include "core/pipeline_settings.h"
#include "gl/caps.h"
#include "gl/gl_api.h"
#include "lesson_render.h"
#include "renderer.h"
#include "scene/default_scene.h"
#include "session/lesson_file.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <emscripten/emscripten.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <sstream>
#include <vector>

namespace gbl {

namespace {

// The page's canvas as a WebGL2 (OpenGL ES 3.0) context of this size, current; null after one
// sentence when the browser gives none.
GLFWwindow* openWebGl2Canvas(int width, int height) {
    if (!glfwInit()) return nullptr;
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    GLFWwindow* window = glfwCreateWindow(width, height, "gbuffer-lab", nullptr, nullptr);
    if (!window) {
        std::fprintf(stderr, "gbuffer-lab: the browser gives no WebGL2 context\n");
        return nullptr;
    }
    glfwMakeContextCurrent(window);
    return window;
}

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

// WebGL2 reads neither depth nor stencil directly; the renderer reads them through passes
// (renderer_readback.cpp). Known values are cleared into the G-buffer's depth-stencil (the left
// half and the right half differ, 5 = 0b101 and 200 = 0b11001000 use six of the eight bit
// planes) and must come back: depth within 24-bit precision, stencil exactly.
std::string readbackProblem(Renderer& renderer) {
    int const w = renderer.width(), h = renderer.height();
    GLuint fbo = 0;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
                           renderer.texture(Attachment::Stencil), 0);
    glEnable(GL_SCISSOR_TEST);
    glStencilMask(0xFF);
    glDepthMask(GL_TRUE);
    auto clearHalf = [&](int x0, int x1, float depth, int stencil) {
        glScissor(x0, 0, x1 - x0, h);
        glClearDepthf(depth);
        glClearStencil(stencil);
        glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    };
    clearHalf(0, w / 2, 0.25f, 5);
    clearHalf(w / 2, w, 0.75f, 200);
    glDisable(GL_SCISSOR_TEST);
    glClearDepthf(1.0f);
    glClearStencil(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    FloatImage const depth = renderer.readAttachment(Attachment::Depth);
    FloatImage const stencil = renderer.readAttachment(Attachment::Stencil);
    if (depth.pixels.size() != std::size_t(w) * std::size_t(h) || stencil.pixels.size() != depth.pixels.size())
        return "the read-backs have the wrong size";
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            bool const left = x < w / 2;
            std::size_t const i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            if (std::abs(depth.pixels[i] - (left ? 0.25f : 0.75f)) > 1e-6f)
                return "depth at (" + std::to_string(x) + ", " + std::to_string(y) + ") reads " +
                       std::to_string(depth.pixels[i]);
            if (stencil.pixels[i] != (left ? 5.0f : 200.0f))
                return "stencil at (" + std::to_string(x) + ", " + std::to_string(y) + ") reads " +
                       std::to_string(stencil.pixels[i]);
        }
    return {};
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
    GLFWwindow* window = openWebGl2Canvas(640, 400);
    if (!window) return 1;
    Renderer renderer(detectGlCaps(), 640, 400);
    int hold = 0, fail = 0, skipped = 0;
    SceneData const scene = makeDefaultScene();
    if (auto err = renderer.setScene(scene)) {
        std::printf("readback-check FAILS: the scene: %s\n", err->c_str());
        ++fail;
    } else {
        renderer.render({scene.camera.value_or(Camera{}), scene.lights, PipelineSettings{}, true});
        std::string const problem = readbackProblem(renderer);
        if (problem.empty())
            std::printf(
                "readback-check: depth and stencil read back as cleared (0.25 and 5, 0.75 and 200) at 640x400\n");
        else
            std::printf("readback-check FAILS: %s\n", problem.c_str());
        fail += problem.empty() ? 0 : 1;
    }
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
        if (step.state.pipeline.msaa != Msaa::Off ||
            (step.claim->reference && step.claim->reference->msaa != Msaa::Off)) {
            skip("MSAA falls back to off in the browser build (WebGL2 has no multisample textures to light from)");
            continue;
        }
        renderer.resizeTargets(lesson.width, lesson.height);
        if (auto err = renderer.setScene(makeDefaultScene({step.defaultSceneLights, step.defaultSceneGlass}))) {
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

int benchRendererInBrowser(std::string const& modeName) {
    auto const mode = enumFromName<LightingMode>(kLightingModeNames, modeName);
    if (!mode) {
        std::fprintf(stderr, "bench-renderer: '%s' is not a lighting mode\n", modeName.c_str());
        return 2;
    }
    GLFWwindow* window = openWebGl2Canvas(1280, 720);
    if (!window) return 1;
    Renderer renderer(detectGlCaps(), 1280, 720);
    if (auto why = renderer.modeUnavailable(*mode)) {
        std::printf("bench-renderer %s: unavailable: %s\n", modeName.c_str(), why->c_str());
        return 0;
    }
    SceneData const scene = makeDefaultScene();
    if (auto err = renderer.setScene(scene)) {
        std::fprintf(stderr, "bench-renderer: %s\n", err->c_str());
        return 1;
    }
    PipelineSettings settings;
    settings.mode = *mode;
    GLuint fbo = 0;
    glGenFramebuffers(1, &fbo);
    auto frame = [&] {
        renderer.render({scene.camera.value_or(Camera{}), scene.lights, settings, false});
        // The one-pixel read waits for the frame: WebGL's finish() does not.
        glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
        glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                               renderer.texture(Attachment::Final), 0);
        GLint format = GL_RGBA, type = GL_UNSIGNED_BYTE;
        glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_FORMAT, &format);
        glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_TYPE, &type);
        std::uint32_t texel[4] = {};
        glReadPixels(0, 0, 1, 1, GLenum(format), GLenum(type), texel);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    };
    for (int i = 0; i < 3; ++i) frame();
    double total = 0.0, fastest = 1e30;
    int const frames = 10;
    for (int i = 0; i < frames; ++i) {
        double const start = emscripten_get_now();
        frame();
        double const ms = emscripten_get_now() - start;
        total += ms;
        fastest = std::min(fastest, ms);
    }
    glDeleteFramebuffers(1, &fbo);
    std::printf(
        "bench-renderer %s: 1280x720, default scene, %zu lights: mean %.1f ms, fastest %.1f ms over %d "
        "frames (each ended by a one-pixel read)\n",
        modeName.c_str(), scene.lights.size(), total / frames, fastest, frames);
    glfwDestroyWindow(window);
    return 0;
}

}  // namespace gbl
