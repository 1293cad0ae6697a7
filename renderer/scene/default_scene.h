// The procedural default scene: a two-storey arcaded courtyard and its orbiting coloured lights.
#pragma once

#include "core/point_light.h"
#include "scene/scene_data.h"

#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace gbl {

struct DefaultSceneOptions {
    int lightCount = 32;  // negative counts as 0
    // Three coloured glass panes (alpha-blended, double-sided) standing in the courtyard between
    // the default camera and the fountain, each its own mesh and instance so the forward pass can
    // sort them back to front. Off by default: every frame without them is unchanged.
    bool glass = false;
};

// The glass panes makeDefaultScene adds, in this order after the courtyard, with `glass` on: world
// centre, turn and size of each (a pane faces +Z before its yaw), and its colour and opacity.
struct GlassPane {
    char const* name;
    glm::vec3 center;
    float yaw;        // radians about +Y; the unrotated pane faces +Z
    glm::vec2 size;   // width, height
    glm::vec4 color;  // linear base colour, alpha = opacity
};
inline constexpr GlassPane kGlassPanes[3] = {
    {"blue glass", {-3.2f, 1.4f, 4.0f}, 0.35f, {2.6f, 2.4f}, {0.15f, 0.35f, 0.95f, 0.4f}},
    {"green glass", {0.0f, 1.4f, 3.4f}, 0.0f, {2.6f, 2.4f}, {0.2f, 0.85f, 0.3f, 0.4f}},
    {"amber glass", {3.2f, 1.4f, 4.0f}, -0.35f, {2.6f, 2.4f}, {0.95f, 0.55f, 0.1f, 0.4f}},
};

// Builds the courtyard (source = "default"): about 33 x 33 units, floor at y = 0, walls 10
// high, arcades on all four sides at |x|, |z| = 12.5 with a gallery between them and the walls,
// and a few dozen props. Static geometry is merged into one mesh per material, each drawn by
// one identity instance. Same options, bit-identical result.
SceneData makeDefaultScene(DefaultSceneOptions const& options = {});

// `count` deterministic coloured point lights spread over the courtyard, 0.5..3 units above
// the floor, with Kc = 1 and Kl, Kq chosen for radii of 4.5..7.5 units (gbl::lightRadius).
// Light i does not depend on count, so fewer lights are a prefix of more.
std::vector<PointLight> makeDefaultLights(int count);

// Moves each light along its circle about the vertical axis through `center`, as after
// `seconds` of orbiting: radius and height are kept, only the angle changes. Light i turns at
// its own deterministic rate (0.15..0.25 rad/s, even indices anticlockwise seen from above,
// odd ones clockwise). seconds = 0 leaves positions bit-identical.
// Use it on a fresh copy of the initial lights each frame:
//     auto lights = initialLights;  orbitLights(lights, defaultSceneCenter(), t);
// so the frame at time t depends only on (initial lights, t), never on the frame history.
void orbitLights(std::span<PointLight> lights, glm::vec3 center, float seconds);

// The point the lights orbit and the default camera looks at: the courtyard's centre on the floor.
glm::vec3 defaultSceneCenter();

}  // namespace gbl
