// Scene and context set-up for the render and bench commands.
#include "scene_setup.h"

#include "gltf/loader.h"
#include "scene/default_scene.h"

#include <cstdio>

namespace gbl {

std::optional<PreparedScene> prepareScene(SceneRequest const& request, std::string* error) {
    PreparedScene out;
    if (request.scenePath) {
        GltfLoadOptions options;
        options.allowOutsideUris = request.allowOutsideUris;
        GltfLoadResult loaded = loadGltf(*request.scenePath, options);
        if (!loaded.scene) {
            *error = loaded.error;
            return std::nullopt;
        }
        out.scene = std::move(*loaded.scene);
        for (auto const& w : out.scene.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
        out.lights = out.scene.lights;
        if (request.lightCount && *request.lightCount < int(out.lights.size()))
            out.lights.resize(std::size_t(*request.lightCount));
    } else {
        DefaultSceneOptions options;
        options.lightCount = request.lightCount.value_or(options.lightCount);
        options.glass = request.glass;
        out.scene = makeDefaultScene(options);
        out.lights = out.scene.lights;
        orbitLights(out.lights, defaultSceneCenter(), request.time);
    }
    out.camera = out.scene.camera.value_or(Camera{});
    return out;
}

std::optional<HeadlessRenderer> createHeadlessRenderer(int width, int height, std::string const& glLimit,
                                                       std::string* error) {
    HeadlessRenderer h;
    h.context = HeadlessContext::create(error);
    if (!h.context) return std::nullopt;
    int major = 0, minor = 0;
    if (!glLimit.empty() && std::sscanf(glLimit.c_str(), "%d.%d", &major, &minor) != 2) {
        *error = "--gl must look like 3.3, got '" + glLimit + "'";
        return std::nullopt;
    }
    GlCaps caps = detectGlCaps(major, minor);
    if (!caps.atLeast(3, 3)) {
        *error = "OpenGL 3.3 is required; this context offers " + caps.version;
        return std::nullopt;
    }
    h.renderer = std::make_unique<Renderer>(caps, width, height);
    return h;
}

}  // namespace gbl
