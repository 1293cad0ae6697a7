// Session files: the scene, camera, lights, pipeline and viewer settings of an editor session as
// versioned JSON, parsed with a message naming the first bad field and applied all or nothing.
#pragma once

#include "core/camera.h"
#include "core/pipeline_settings.h"
#include "core/point_light.h"
#include "model/lights_state.h"
#include "model/viewer_state.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gbl::ui {

inline constexpr std::string_view kSessionFormat = "gbuffer-lab-session";
// Bump when a field changes meaning or a required field is added; older files then get a
// message instead of being read wrongly. Optional fields (the viewer tools) need no bump: files
// without them load with the defaults.
inline constexpr int kSessionVersion = 1;

struct Session {
    // "default" for the procedural courtyard, else the glTF file's path.
    std::string scene = "default";
    // Lights the default scene was built with (the lights below are the ones used; this
    // tells a reader how the session started).
    int defaultSceneLights = 32;
    // The default scene's glass panes (DefaultSceneOptions::glass); "default_scene_glass", optional
    // and written only when on, so files without it load and sessions without glass are unchanged.
    bool defaultSceneGlass = false;
    Camera camera;
    // The lights as edited, before animation; shown lights are these orbited by animation.time.
    std::vector<PointLight> lights;
    PipelineSettings pipeline;
    std::array<ViewerState, 5> viewers = GBufferPanelState::defaultViewers();
    LightAnimation animation;
    // Viewer tools (optional in the file: a session without them gets these defaults).
    bool syncViews = false;          // "Sync zoom/pan" of the G-buffer viewers
    bool viewportToolsOpen = false;  // the viewport's Tools toggle
    ViewerState viewportViewer = ViewportTools::defaultViewer();
};

// The session as JSON text (2-space indent). Floats are written with enough digits to read
// back bit-identical, so a saved session reproduces the same frame.
std::string sessionToJson(Session const& session);

struct SessionLoad {
    std::optional<Session> session;  // whole, or nothing
    std::string error;               // "<file>: <field> <what is wrong>" when session is empty
};

// Parses and validates a session. `fileLabel` starts every message ("session.json: ...").
// Every field is checked before anything is returned, so the caller never sees a session that
// is half valid.
SessionLoad parseSession(std::string_view text, std::string const& fileLabel);
SessionLoad loadSession(std::string const& path);

// Writes the session atomically (see atomic_file.h). Returns an error sentence on failure.
std::optional<std::string> saveSession(std::string const& path, Session const& session);

}  // namespace gbl::ui
