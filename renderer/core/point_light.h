// A point light as the editor, the renderer and session files see it.
#pragma once

#include <glm/glm.hpp>

#include <string>

namespace gbl {

// Cut-off brightness used by the classic texts: a light is "dark enough" below 5/256.
inline constexpr float kDefaultLightThreshold = 5.0f / 256.0f;

// Most lights any scene, session or command accepts; more are refused with this number.
inline constexpr int kMaxLights = 16384;

struct PointLight {
    glm::vec3 position{0.0f};
    glm::vec3 color{1.0f};   // linear RGB, 0..1 per channel
    float intensity = 1.0f;  // multiplies color; Imax = intensity * max(color)
    float kc = 1.0f;         // constant attenuation term
    float kl = 0.7f;         // linear attenuation term
    float kq = 1.8f;         // quadratic attenuation term
    float threshold = kDefaultLightThreshold;
    std::string name;

    // Every member, floats compared with ==: exactly what undo's "did this edit change anything"
    // asks. NaN, which never equals itself, never reaches a stored light: validateLight() refuses
    // it for edits (applyLightEdit) and session files, and the glTF loader refuses it as well.
    bool operator==(PointLight const&) const = default;
};

}  // namespace gbl
