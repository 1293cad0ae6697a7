// Small scenes with known geometry for analytic GL tests.
#pragma once

#include "core/camera.h"
#include "core/pipeline_settings.h"
#include "scene/scene_data.h"

namespace gbl::test {

inline constexpr glm::vec3 kPlaneAlbedo{0.6f, 0.5f, 0.4f};
inline constexpr float kPlaneSpecular = 0.25f;

// A 40 x 40 floor at y = 0 facing +Y, one untextured material.
SceneData floorScene();
// floorScene() plus a 6 x 4 wall in the plane z = 0, facing +Z (towards a camera at z > 0).
SceneData floorAndWallScene();

// One light 1 unit above floorScene()'s floor, off its centre (radius ~6.2): seen from (0, 8, 6)
// looking at the origin, part of the visible floor is lit and part lies beyond its reach.
PointLight floorTestLight();

// The settings of the analytic tests: the lighting alone (no light cubes), ambient 0.03.
PipelineSettings plainSettings();

// A camera at `from` looking at `target`, near 0.1 and far 100.
Camera lookingAt(glm::vec3 from, glm::vec3 target);

// The world-space ray through the centre of pixel (x, y) of a w x h frame, y from the top.
struct Ray {
    glm::vec3 origin, dir;
};
Ray pixelRay(Camera const& c, int w, int h, int x, int y);

}  // namespace gbl::test
