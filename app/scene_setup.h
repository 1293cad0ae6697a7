// What the headless commands share: a GL context, a renderer and a scene with lights and camera.
#pragma once

#include "core/camera.h"
#include "gl/headless_context.h"
#include "renderer.h"
#include "scene/scene_data.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gbl {

struct SceneRequest {
    std::optional<std::string> scenePath;  // glTF file; the default scene when empty
    std::optional<int> lightCount;         // default scene: how many lights (32 when unset)
    float time = 0.0f;                     // seconds of light orbiting (default scene)
    bool allowOutsideUris = false;
    bool glass = false;  // default scene: its glass panes (DefaultSceneOptions::glass)
};

struct PreparedScene {
    SceneData scene;
    std::vector<PointLight> lights;
    Camera camera;
};

// Builds the default scene or loads the glTF file. On failure returns nullopt with one sentence.
std::optional<PreparedScene> prepareScene(SceneRequest const& request, std::string* error);

struct HeadlessRenderer {
    std::unique_ptr<HeadlessContext> context;
    std::unique_ptr<Renderer> renderer;
};

// A headless context and a renderer of the given size. glLimit "3.3" pretends the context is
// at most that version. On failure returns nullopt with one sentence.
std::optional<HeadlessRenderer> createHeadlessRenderer(int width, int height, std::string const& glLimit,
                                                       std::string* error);

}  // namespace gbl
