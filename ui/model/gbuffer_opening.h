// Opening another program's G-buffer in the editor (issue 28): File > Open G-buffer, a dropped
// manifest or folder, --gbuffer. The frame is re-lit live with the manifest's lights, from the
// manifest's camera; closing it gives back the scene's camera and lights as they were.
#pragma once

#include "core/camera.h"
#include "core/frame_types.h"
#include "core/imported_frame.h"
#include "core/point_light.h"
#include "import/gbuffer_checks.h"
#include "model/camera_rig.h"
#include "model/editor_state.h"
#include "model/file_browser.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace gbl::ui {

// What opening a G-buffer replaces, kept to be given back when it is closed.
struct SceneViewSnapshot {
    Camera camera;
    CameraRig rig;
    std::vector<PointLight> lights;
    int selectedLight = -1;
    float shininess = 32.0f;
    ShadingModel shading = ShadingModel::GbufferLab;
    glm::vec3 ambient{0.03f};
};

struct GBufferOpenState {
    std::vector<std::string> requests;  // paths asked for (menu, drop, --gbuffer, script), oldest first
    bool closeRequested = false;        // File > Close G-buffer
    std::string path;                   // the G-buffer shown ("" = the scene is shown)
    glm::ivec2 size{0};                 // its frame size
    std::optional<SceneViewSnapshot> scene;
    GBufferCheckReport checks;  // the shown G-buffer's findings, masks included
    std::string lastError;      // the last refused open ("" after a good one)
    FileBrowserState browser;
    // File > "Open G-buffer..." as drawn while the File menu is open (0 otherwise), for the frame log.
    glm::vec4 menuItemRect{0.0f};
};

// A G-buffer read from disk and ready to upload: the frame, its lights, shininess and camera.
struct GBufferRead {
    std::optional<ImportedFrame> frame;
    std::vector<PointLight> lights;
    float shininess = 32.0f;
    ShadingModel shading = ShadingModel::GbufferLab;  // the manifest's "shading"
    // The program's own lit image (the manifest's "lit"), rows top-down, RGBA with A = 1; it is
    // pinned in the viewport so that Diff compares our re-light with it.
    std::optional<FloatImage> lit;
    std::string litFile;        // its file name, for the pin's label
    GBufferCheckReport checks;  // what `check` finds in it (docs/import.md, "Checks")
    Camera camera;
    std::string error;  // one sentence naming the file and the field when frame is empty
};

// Reads a manifest, or a folder holding one (or a `render --out` folder), its images, and builds
// the frame to re-light (renderer/import). No GL.
GBufferRead readGBuffer(std::string const& path);

// Whether a dropped path is a G-buffer rather than a scene: a folder, or a .json manifest
// (scenes are .gltf / .glb).
bool isGBufferPath(std::string const& path);

// Moves the G-buffer paths among `dropped` to `requests` (the last one wins), leaving the scenes.
void takeGBufferDrops(std::vector<std::string>& dropped, GBufferOpenState& state);

// Hands the frame to the GPU (the editor passes Renderer::setImportedGBuffer): nullopt or why not.
using GBufferUploader = std::function<std::optional<std::string>(ImportedFrame const&)>;

// Makes a read G-buffer the one shown: uploads it, then takes its camera, lights and shininess,
// keeping the scene's to give back (a second open keeps the first snapshot). On failure nothing
// changes and the error sentence is returned.
std::optional<std::string> installGBuffer(GBufferOpenState& state, std::string const& path, GBufferRead const& read,
                                          EditorState& editor, GBufferUploader const& upload);

// Gives back the scene's camera, lights and shininess (the caller clears the renderer's frame).
void closeGBuffer(GBufferOpenState& state, EditorState& editor);
// Forgets the G-buffer without giving anything back: a new scene brought its own camera and lights.
void forgetGBuffer(GBufferOpenState& state, EditorState& editor);

bool gbufferOpen(GBufferOpenState const& state);

// The editor's state with the scene's camera, lights and shininess in place of an open G-buffer's:
// what a session's unsaved edits are judged on (the G-buffer's lights are not the session's).
EditorState sceneBehind(EditorState state, GBufferOpenState const& gbuffer);

enum class GBufferChange { None, Opened, Closed, Failed };

// Once per frame, on the render thread: a close request, then the requests in order. Each
// refused one logs one error sentence ending in what stays shown; the previous frame stays.
// `clear` removes the renderer's imported frame on close. Returns what changed last.
GBufferChange updateGBufferOpening(GBufferOpenState& state, EditorState& editor, GBufferUploader const& upload,
                                   std::function<void()> const& clear);

}  // namespace gbl::ui
