// What the deferred frame depends on, as one comparable value: the editor renders again only when
// this changed (or continuous rendering is on), and otherwise shows the last frame and viewers.
#pragma once

#include "core/camera.h"
#include "core/frame_passes.h"
#include "core/pipeline_settings.h"
#include "core/point_light.h"
#include "model/ab_compare.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace gbl::ui {

struct RenderInputs {
    // The camera as the renderer uses it: its matrices (position, orientation, field of view and
    // clip planes all end up in them) and its position (specular highlights).
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::vec3 cameraPosition{0.0f};
    std::vector<PointLight> lights;  // as drawn this frame (animated lights have moved)
    PipelineSettings pipeline;
    glm::ivec2 size{0};                  // the renderer's targets
    std::uint64_t sceneGeneration = 0;   // counts scenes handed to Renderer::setScene
    std::uint64_t shaderGeneration = 0;  // counts hot reloads that replaced a program
    float animationTime = 0.0f;
    bool measuring = false;           // a cost measurement times real frames, so each of its frames renders
    TeachingInputs teaching;          // the scrubber, the wireframe option and A/B's side B
    std::optional<PassId> stopAfter;  // the Frame window's stop after a pass

    bool operator==(RenderInputs const&) const = default;
};

RenderInputs renderInputs(Camera const& camera, std::span<PointLight const> lights, PipelineSettings const& pipeline,
                          glm::ivec2 size, std::uint64_t sceneGeneration, std::uint64_t shaderGeneration,
                          float animationTime, bool measuring);

// The loop's memory of the last rendered frame and its decision for this one.
struct RenderOnChange {
    bool continuous = false;           // --continuous / the Stats checkbox: render every frame (timing)
    std::optional<RenderInputs> last;  // what the frame on screen was rendered from
    bool renderedLastFrame = false;
    long renders = 0;  // frames the renderer ran, since start
    long skipped = 0;  // frames that reused the last image
};

// True when the renderer must run for `now`: nothing rendered yet, an input changed, or
// continuous rendering is on. Records the decision (renderedLastFrame, counters, last).
bool needsRender(RenderOnChange& state, RenderInputs const& now);

// "re-rendered: camera, lights" / "reused the last frame": what the Stats window shows.
std::string describeChange(std::optional<RenderInputs> const& before, RenderInputs const& now);

}  // namespace gbl::ui
