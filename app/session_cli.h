// Sessions on the command line: building the frame a session describes, and describing a
// command-line frame as a session (`render --session`, `render --save-session`, `bench --session`).
#pragma once

#include "core/pipeline_settings.h"
#include "scene_setup.h"
#include "session/session.h"

#include <optional>
#include <string>

namespace gbl {

// The scene a session names (the default courtyard, or its glTF file), with the session's
// camera and its lights placed as the editor shows them: orbited by animation.time about the
// courtyard centre (default scene) or the scene bounds' centre (glTF), as ui/editor/editor.cpp does.
// On failure nullopt and one sentence naming the session file.
std::optional<PreparedScene> prepareSessionScene(ui::Session const& session, std::string const& sessionPath,
                                                 bool allowOutsideUris, std::string* error);

// Applies an already prepared scene's session values: camera, lights (orbited as above) and
// the pipeline settings. The scene geometry is left as it is.
void applySession(ui::Session const& session, PreparedScene& prepared, PipelineSettings& settings);

// The session that reproduces a command-line frame. `request` is what prepareScene was given,
// `prepared` its result and `settings` the pipeline used. The lights stored are the un-orbited
// ones, with animation.time = request.time for the default scene (the only scene the command
// line orbits), so loading it renders the same frame.
ui::Session sessionFromCommandLine(SceneRequest const& request, PreparedScene const& prepared,
                                   PipelineSettings const& settings);

// The point lights orbit about for a scene (what the editor uses).
glm::vec3 sessionOrbitCenter(std::string const& sceneSource, SceneData const& scene);

}  // namespace gbl
