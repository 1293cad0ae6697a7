// gbuffer-lab in the browser, first slice (issue 29): the renderer draws the default scene into the
// page's canvas through WebGL2 every animation frame, with a small Dear ImGui window over it. The
// editor (ui/) is not built for the web yet; the README's "In the browser" notes say what is left.
#include "core/pipeline_settings.h"
#include "core/view_params.h"
#include "gl/caps.h"
#include "gl/gl_api.h"
#include "gpu/view_target.h"
#include "renderer.h"
#include "scene/default_scene.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <emscripten/emscripten.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

struct App {
    GLFWwindow* window = nullptr;
    std::unique_ptr<gbl::Renderer> renderer;
    gbl::SceneData scene;
    std::vector<gbl::PointLight> initialLights;
    std::vector<gbl::PointLight> lights;
    gbl::Camera camera;
    gbl::PipelineSettings settings;
    gbl::ViewTarget view;
    double startTime = 0.0;
    double lastTime = 0.0;
    bool animate = true;
    int frames = 0;
};

App* gApp = nullptr;

void frameBody() {
    App& app = *gApp;
    int width = 0, height = 0;
    glfwGetFramebufferSize(app.window, &width, &height);
    if (width <= 0 || height <= 0) return;
    if (width != app.renderer->width() || height != app.renderer->height()) app.renderer->resizeTargets(width, height);

    double const now = glfwGetTime();
    if (app.animate) {
        app.lights = app.initialLights;
        gbl::orbitLights(app.lights, gbl::defaultSceneCenter(), float(now - app.startTime));
    }

    gbl::FrameInput input;
    input.camera = app.camera;
    input.lights = app.lights;
    input.settings = app.settings;
    input.waitForGpuTimings = false;
    app.renderer->render(input);
    app.renderer->drawView(gbl::ViewParams{}, input, app.view);

    // The view target (RGBA8, tonemapped) onto the canvas.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, app.view.fbo.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);

    // ImGui asserts on a zero delta time, which a headless browser's virtual time gives.
    ImGui::GetIO().DeltaTime = float(std::max(now - app.lastTime, 1e-4));
    app.lastTime = now;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    if (ImGui::GetIO().DeltaTime <= 0.0f) ImGui::GetIO().DeltaTime = 1e-4f;
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::Begin("gbuffer-lab (web)");
    gbl::GlCaps const& caps = app.renderer->caps();
    ImGui::Text("%s", caps.renderer.c_str());
    ImGui::Text("%s", caps.version.c_str());
    ImGui::Text("%d x %d, %d lights, %.1f ms/frame", width, height, int(app.lights.size()),
                1000.0f / std::max(ImGui::GetIO().Framerate, 1e-3f));
    ImGui::Checkbox("Animate lights", &app.animate);
    ImGui::SliderFloat("Exposure", &app.settings.exposure, 0.05f, 8.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
    for (auto mode : {gbl::LightingMode::Quad, gbl::LightingMode::Volumes, gbl::LightingMode::Forward,
                      gbl::LightingMode::Tiled, gbl::LightingMode::Clustered}) {
        std::optional<std::string> const why = app.renderer->modeUnavailable(mode);
        std::string const name(gbl::kLightingModeNames[std::size_t(mode)]);
        if (why) ImGui::BeginDisabled();
        if (ImGui::RadioButton(name.c_str(), app.settings.mode == mode)) app.settings.mode = mode;
        if (why) {
            ImGui::EndDisabled();
            if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", why->c_str());
        }
    }
    ImGui::End();
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

    if (++app.frames == 1) std::printf("gbuffer-lab (web): first frame drawn, %d x %d\n", width, height);
}

void frame() {
    try {
        frameBody();
    } catch (std::exception const& e) {
        std::fprintf(stderr, "gbuffer-lab (web): error: %s\n", e.what());
        emscripten_cancel_main_loop();
    }
}

int run();

}  // namespace

int main() {
    // Exceptions are compiled in (cmake/web.cmake); one that reaches here is printed, not an "Uncaught <number>".
    try {
        return run();
    } catch (std::exception const& e) {
        std::fprintf(stderr, "gbuffer-lab (web): error: %s\n", e.what());
        return 1;
    }
}

namespace {

int run() {
    if (!glfwInit()) {
        std::fprintf(stderr, "gbuffer-lab (web): glfwInit failed\n");
        return 1;
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    int width = 1280, height = 720;
    static App app;
    gApp = &app;
    app.window = glfwCreateWindow(width, height, "gbuffer-lab", nullptr, nullptr);
    if (!app.window) {
        std::fprintf(stderr, "gbuffer-lab (web): no WebGL2 context\n");
        return 1;
    }
    glfwMakeContextCurrent(app.window);
    glfwGetFramebufferSize(app.window, &width, &height);

    gbl::GlCaps const caps = gbl::detectGlCaps();
    std::printf("gbuffer-lab (web): %s; %s; GLSL %s\n", caps.renderer.c_str(), caps.version.c_str(),
                caps.glslVersion.c_str());
    if (!gbl::gl::hasExtension("GL_EXT_color_buffer_float"))
        std::fprintf(stderr,
                     "gbuffer-lab (web): EXT_color_buffer_float is missing: the float G-buffer cannot be drawn\n");
    app.renderer = std::make_unique<gbl::Renderer>(caps, width, height);
    app.scene = gbl::makeDefaultScene();
    if (auto error = app.renderer->setScene(app.scene))
        std::fprintf(stderr, "gbuffer-lab (web): scene: %s\n", error->c_str());
    app.initialLights = app.scene.lights;
    app.lights = app.initialLights;
    app.camera = app.scene.camera.value_or(gbl::Camera{});
    app.startTime = app.lastTime = glfwGetTime();

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // the layout in the browser's storage comes later (IDBFS)
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(app.window, true);
    ImGui_ImplOpenGL3_Init("#version 300 es");

    emscripten_set_main_loop(frame, 0, false);
    return 0;
}

}  // namespace
