// Named camera views of the editor: the scene's home view (Home), the file's own cameras and framing
// the selection (F).
// Pure math over the rig and camera, no GL.
#pragma once

#include "core/camera.h"
#include "model/camera_rig.h"
#include "scene/scene_data.h"

#include <optional>
#include <string>
#include <vector>

namespace gbl::ui {

// A camera with the rig target it orbits around.
struct CameraView {
    Camera camera;
    CameraRig rig;
};

// The view a scene starts in: its suggested camera, or, without one, the whole scene framed
// from the default direction. Captured when a scene is installed; Home returns to it.
CameraView homeView(std::optional<Camera> const& suggested, Bounds const& bounds, CameraRig const& rig);

// A view the View menu offers by name.
struct NamedView {
    std::string name;
    CameraView view;
};

// The scene file's cameras (SceneData::cameras) as views, in file order: each camera as the file
// places it, its rig orbiting a point ahead of it at the distance of the scene's centre, so that
// orbiting after choosing one turns about the scene rather than the camera.
std::vector<NamedView> sceneCameraViews(std::vector<SceneCamera> const& cameras, Bounds const& bounds,
                                        CameraRig const& rig);

bool insideBounds(glm::vec3 point, Bounds const& bounds);

// F with a light selected: the light at the centre of the view, seen from the current direction
// at a distance that shows the cube and what it lights near by (half its radius, at least 1,
// at most a third of the scene's radius, and never less than 1).
void frameLight(CameraRig& rig, Camera& camera, glm::vec3 lightPosition, float lightRadius, Bounds const& scene);

// F with nothing selected: the home view when it looks at the scene from inside (a courtyard is
// seen from within its walls), else the whole scene framed from the current direction.
void frameNothingSelected(CameraRig& rig, Camera& camera, CameraView const& home, Bounds const& scene);

}  // namespace gbl::ui
