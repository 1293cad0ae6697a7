// Home view, the file's cameras and framing the selection.
#include "model/camera_views.h"

#include <algorithm>

namespace gbl::ui {

CameraView homeView(std::optional<Camera> const& suggested, Bounds const& bounds, CameraRig const& rig) {
    CameraView v;
    v.rig = rig;
    if (suggested) {
        v.camera = *suggested;
        resetTargetAhead(v.rig, v.camera, glm::length(v.camera.position - bounds.center()));
    } else {
        frameBounds(v.rig, v.camera, bounds);
    }
    return v;
}

std::vector<NamedView> sceneCameraViews(std::vector<SceneCamera> const& cameras, Bounds const& bounds,
                                        CameraRig const& rig) {
    std::vector<NamedView> views;
    for (auto const& c : cameras) {
        NamedView v{c.name, {c.camera, rig}};
        // At least the near plane ahead: a camera inside the scene's centre still orbits something in view.
        float const distance = std::max(glm::length(c.camera.position - bounds.center()), c.camera.nearPlane);
        resetTargetAhead(v.view.rig, v.view.camera, distance);
        views.push_back(std::move(v));
    }
    return views;
}

bool insideBounds(glm::vec3 p, Bounds const& b) {
    return glm::all(glm::greaterThanEqual(p, b.min)) && glm::all(glm::lessThanEqual(p, b.max));
}

void frameLight(CameraRig& rig, Camera& camera, glm::vec3 lightPosition, float lightRadius, Bounds const& scene) {
    float const far = std::max(scene.radius() / 3.0f, 1.0f);
    float const distance = std::clamp(lightRadius * 0.5f, 1.0f, far);
    rig.target = lightPosition;
    camera.position = lightPosition - camera.forward() * distance;
}

void frameNothingSelected(CameraRig& rig, Camera& camera, CameraView const& home, Bounds const& scene) {
    if (insideBounds(home.camera.position, scene)) {
        camera = home.camera;
        rig = home.rig;
        return;
    }
    frameBounds(rig, camera, scene);
}

}  // namespace gbl::ui
