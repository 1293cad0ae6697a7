// The documented mappings from glTF to our model (docs/gltf.md): specular, lights, framing.
#pragma once

#include "core/camera.h"
#include "core/point_light.h"
#include "scene/scene_data.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gbl {

// glTF lights are in candela and its BRDF divides Lambert by pi; our Lambert term does not, so a
// glTF intensity I (cd) becomes I / pi to light a surface equally at the same distance.
inline constexpr float kGltfCandelaToIntensity = 0.318309886f;  // 1 / pi

// Specular intensity stored in the G-buffer, from glTF metallic-roughness and the dielectric
// weight of KHR_materials_specular (1 without the extension):
//   (1 - roughness)^2 * mix(0.5 * weight, 1, metallic), clamped to [0, 1].
float specularFromMetallicRoughness(float metallic, float roughness, float dielectricWeight = 1.0f);

// A light with Kc = 1, Kl = 0 and Kq chosen so that solveLightRadius() returns `radius`.
// When the light is too dim to ever reach the threshold, Kq = 1 and the radius is 0.
PointLight pointLightWithRadius(glm::vec3 position, glm::vec3 color, float intensity, float radius, std::string name);

// A KHR_lights_punctual point light. range <= 0 means "infinite" in glTF: we then keep the
// inverse-square law of the file (Kc = 1, Kl = 0, Kq = 1 per square scene unit) and let the
// threshold decide the radius. Returns nullopt (with the reason) for unusable values.
std::optional<PointLight> pointLightFromGltf(glm::vec3 position, glm::vec3 color, float intensityCandela, float range,
                                             std::string name, std::string* why = nullptr);

// A deterministic light set for scenes without lights: four white key lights around and above
// the bounds that reach the whole scene, and twelve small coloured lights spread through it.
std::vector<PointLight> generateLightsForBounds(Bounds const& bounds);

// A glTF perspective camera placed by its node's world matrix: at the matrix's origin, looking
// down its -Z axis (glTF's camera convention), with yfov in radians. Our camera has no roll, so
// a node that rolls the camera about its view axis is shown upright. zfar <= 0 means glTF's
// infinite projection; `fallbackFar` (a distance that holds the scene) is used then.
Camera cameraFromGltf(glm::mat4 const& world, float yfovRadians, float znear, float zfar, float fallbackFar);

// A camera looking at the bounds' centre from the front (+Z) and a little above, far enough
// for the bounding sphere to fit the vertical field of view, with near/far planes scaled to it.
Camera frameBounds(Bounds const& bounds, float fovYDegrees = 60.0f);

}  // namespace gbl
