// Render-on-change: building the record of what a frame depends on and deciding to render.
#include "model/render_inputs.h"

namespace gbl::ui {

RenderInputs renderInputs(Camera const& camera, std::span<PointLight const> lights, PipelineSettings const& pipeline,
                          glm::ivec2 size, std::uint64_t sceneGeneration, std::uint64_t shaderGeneration,
                          float animationTime, bool measuring) {
    RenderInputs r;
    float const aspect = size.y > 0 ? float(size.x) / float(size.y) : 1.0f;
    r.view = camera.view();
    r.projection = camera.projection(aspect);
    r.cameraPosition = camera.position;
    r.lights.assign(lights.begin(), lights.end());
    r.pipeline = pipeline;
    r.size = size;
    r.sceneGeneration = sceneGeneration;
    r.shaderGeneration = shaderGeneration;
    r.animationTime = animationTime;
    r.measuring = measuring;
    return r;
}

bool needsRender(RenderOnChange& state, RenderInputs const& now) {
    bool const render = state.continuous || now.measuring || !state.last || !(*state.last == now);
    state.renderedLastFrame = render;
    if (render) {
        ++state.renders;
        state.last = now;
    } else {
        ++state.skipped;
    }
    return render;
}

std::string describeChange(std::optional<RenderInputs> const& before, RenderInputs const& now) {
    if (!before) return "first frame";
    std::string out;
    auto add = [&](bool changed, char const* what) {
        if (!changed) return;
        if (!out.empty()) out += ", ";
        out += what;
    };
    add(before->view != now.view || before->projection != now.projection ||
            before->cameraPosition != now.cameraPosition,
        "camera");
    add(!(before->lights == now.lights), "lights");
    add(!(before->pipeline == now.pipeline), "pipeline");
    add(before->size != now.size, "size");
    add(before->sceneGeneration != now.sceneGeneration, "scene");
    add(before->shaderGeneration != now.shaderGeneration, "shaders");
    add(before->animationTime != now.animationTime, "animation");
    add(!(before->teaching == now.teaching), "accumulation or A/B");
    add(before->stopAfter != now.stopAfter, "stop after a pass");
    add(now.measuring, "measuring");
    return out.empty() ? std::string("nothing") : out;
}

}  // namespace gbl::ui
