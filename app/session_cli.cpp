// Sessions for the headless commands: session -> prepared scene, and command line -> session.
#include "session_cli.h"

#include "scene/default_scene.h"

namespace gbl {

glm::vec3 sessionOrbitCenter(std::string const& sceneSource, SceneData const& scene) {
    return sceneSource == "default" ? defaultSceneCenter() : scene.bounds().center();
}

void applySession(ui::Session const& session, PreparedScene& prepared, PipelineSettings& settings) {
    prepared.camera = session.camera;
    prepared.lights = session.lights;
    // Same rule as the editor: the shown lights are the edited ones orbited by the animation
    // time, whether the animation is running or paused.
    if (session.animation.time != 0.0f)
        orbitLights(prepared.lights, sessionOrbitCenter(session.scene, prepared.scene), session.animation.time);
    settings = session.pipeline;
}

std::optional<PreparedScene> prepareSessionScene(ui::Session const& session, std::string const& sessionPath,
                                                 bool allowOutsideUris, std::string* error) {
    SceneRequest request;
    if (session.scene != "default")
        request.scenePath = session.scene;
    else {
        request.lightCount = session.defaultSceneLights;
        request.glass = session.defaultSceneGlass;
    }
    request.allowOutsideUris = allowOutsideUris;
    auto prepared = prepareScene(request, error);
    if (!prepared) {
        *error = sessionPath + ": scene " + session.scene + " cannot be opened: " + *error;
        return std::nullopt;
    }
    PipelineSettings ignored;
    applySession(session, *prepared, ignored);
    return prepared;
}

ui::Session sessionFromCommandLine(SceneRequest const& request, PreparedScene const& prepared,
                                   PipelineSettings const& settings) {
    ui::Session s;
    s.camera = prepared.camera;
    s.pipeline = settings;
    if (request.scenePath) {
        s.scene = *request.scenePath;
        // glTF lights are not orbited on the command line: they are stored as rendered.
        s.lights = prepared.lights;
        s.animation.time = 0.0f;
    } else {
        s.scene = "default";
        s.defaultSceneLights = int(prepared.scene.lights.size());
        s.defaultSceneGlass = request.glass;
        // The scene keeps the lights before orbiting; prepared.lights are them at request.time.
        s.lights = prepared.scene.lights;
        s.animation.time = request.time;
    }
    s.animation.enabled = false;
    return s;
}

}  // namespace gbl
