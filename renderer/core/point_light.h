// A light as the editor, the renderer and session files see it (point, spot or directional; the
// type keeps its historical name), and the table of its numbers.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace gbl {

// Cut-off brightness used by the classic texts: a light is "dark enough" below 5/256.
inline constexpr float kDefaultLightThreshold = 5.0f / 256.0f;

// Most lights any scene, session or command accepts; more are refused with this number.
inline constexpr int kMaxLights = 262144;

// Most directional lights a frame shades (MAX_DIRECTIONAL_LIGHTS in shaders/light_fetch.glsl).
inline constexpr int kMaxDirectionalLights = 8;

// Widest outer cone of a spot light, in degrees (KHR_lights_punctual allows (0, 90]).
inline constexpr float kMaxSpotConeDeg = 90.0f;

// What a light is (docs/lighting.md, "Light kinds"):
//   Point:       position, radius from the attenuation, every direction.
//   Spot:        a point light times the cone factor of `direction`, innerConeDeg, outerConeDeg.
//   Directional: `direction` only, no attenuation and no radius: lights every pixel, shaded by
//                the full-screen global-lights loop of every mode (position is only where the
//                viewport draws its arrow).
enum class LightKind { Point, Spot, Directional };

// Names in session files, lights.json, the UI script and the panel, in enum order.
inline constexpr std::array<std::string_view, 3> kLightKindNames{"point", "spot", "directional"};

inline std::string_view lightKindName(LightKind k) {
    auto const i = static_cast<std::size_t>(k);
    return i < kLightKindNames.size() ? kLightKindNames[i] : std::string_view("?");
}

struct PointLight {
    LightKind kind = LightKind::Point;
    glm::vec3 position{0.0f};
    glm::vec3 color{1.0f};   // linear RGB, 0..1 per channel
    float intensity = 1.0f;  // multiplies color; Imax = intensity * max(color)
    float kc = 1.0f;         // constant attenuation term
    float kl = 0.7f;         // linear attenuation term
    float kq = 1.8f;         // quadratic attenuation term
    float threshold = kDefaultLightThreshold;
    // Where a spot or directional light shines (need not be unit length; must not be zero).
    glm::vec3 direction{0.0f, -1.0f, 0.0f};
    // Spot cone half-angles in degrees from `direction`: full light inside inner, none outside
    // outer; 0 <= inner <= outer <= kMaxSpotConeDeg, outer > 0 (KHR_lights_punctual's defaults).
    float innerConeDeg = 0.0f;
    float outerConeDeg = 45.0f;
    std::string name;

    // Every member, floats compared with ==: exactly what undo's "did this edit change anything"
    // asks. NaN, which never equals itself, never reaches a stored light: validateLight() refuses
    // it for edits (applyLightEdit) and session files, and the glTF loader refuses it as well.
    bool operator==(PointLight const&) const = default;
};

// What validateLight() demands of a number.
enum class LightFieldRange {
    Finite,       // any finite value (position)
    NonNegative,  // finite and >= 0 (colour, intensity, attenuation, threshold)
    Direction,    // finite; the three together must not be the zero vector
    ConeAngle,    // degrees in [0, kMaxSpotConeDeg]; also inner <= outer and outer > 0
};

// One editable number of a light: a float member or one component of a vec3 member.
struct LightField {
    std::string_view name;   // the UI script's name: x y z r g b intensity kc kl kq threshold dx dy dz inner outer
    std::string_view label;  // the name in error sentences: "position.x", "color.r", "Kc"
    LightFieldRange range;
    float PointLight::*scalar = nullptr;
    glm::vec3 PointLight::*vector = nullptr;
    int component = 0;
    // Session files and G-buffer manifests (docs/sessions.md): the key, shared by a vector's three
    // components ("position": [x, y, z]), and whether files written before the field existed may
    // leave it out (then the light keeps its default).
    std::string_view fileKey;
    bool optionalInFiles = false;
    bool positive = false;  // zero is refused too (the threshold: Imax / 0 has no radius)

    float& of(PointLight& l) const { return scalar ? l.*scalar : (l.*vector)[component]; }
    float of(PointLight const& l) const { return scalar ? l.*scalar : (l.*vector)[component]; }
};

// Every number of PointLight, once: validateLight() checks these, session files and G-buffer
// manifests read and write them (core/json_fields.h), and the UI script's `light` and
// `expect-light` commands read and write them. tests/light_math_test.cpp fails to compile when
// PointLight gains a member (a structured binding of all members) and fails when an entry does
// not change the light it edits. `kind` is not a number: the script's `light N kind NAME` and the
// panel's combo set it.
inline constexpr std::array<LightField, 16> kLightFields{{
    {"x", "position.x", LightFieldRange::Finite, nullptr, &PointLight::position, 0, "position"},
    {"y", "position.y", LightFieldRange::Finite, nullptr, &PointLight::position, 1, "position"},
    {"z", "position.z", LightFieldRange::Finite, nullptr, &PointLight::position, 2, "position"},
    {"r", "color.r", LightFieldRange::NonNegative, nullptr, &PointLight::color, 0, "color"},
    {"g", "color.g", LightFieldRange::NonNegative, nullptr, &PointLight::color, 1, "color"},
    {"b", "color.b", LightFieldRange::NonNegative, nullptr, &PointLight::color, 2, "color"},
    {"intensity", "intensity", LightFieldRange::NonNegative, &PointLight::intensity, nullptr, 0, "intensity"},
    {"kc", "Kc", LightFieldRange::NonNegative, &PointLight::kc, nullptr, 0, "kc"},
    {"kl", "Kl", LightFieldRange::NonNegative, &PointLight::kl, nullptr, 0, "kl"},
    {"kq", "Kq", LightFieldRange::NonNegative, &PointLight::kq, nullptr, 0, "kq"},
    {"threshold", "threshold", LightFieldRange::NonNegative, &PointLight::threshold, nullptr, 0, "threshold", false,
     true},
    {"dx", "direction.x", LightFieldRange::Direction, nullptr, &PointLight::direction, 0, "direction", true},
    {"dy", "direction.y", LightFieldRange::Direction, nullptr, &PointLight::direction, 1, "direction", true},
    {"dz", "direction.z", LightFieldRange::Direction, nullptr, &PointLight::direction, 2, "direction", true},
    {"inner", "inner_cone_deg", LightFieldRange::ConeAngle, &PointLight::innerConeDeg, nullptr, 0, "inner_cone_deg",
     true},
    {"outer", "outer_cone_deg", LightFieldRange::ConeAngle, &PointLight::outerConeDeg, nullptr, 0, "outer_cone_deg",
     true},
}};

// The entry of kLightFields called `name`, or nullptr.
inline LightField const* findLightField(std::string_view name) {
    for (LightField const& f : kLightFields)
        if (f.name == name) return &f;
    return nullptr;
}

// The kind called `name` ("point", "spot", "directional"), or nullopt.
inline std::optional<LightKind> findLightKind(std::string_view name) {
    for (std::size_t i = 0; i < kLightKindNames.size(); ++i)
        if (kLightKindNames[i] == name) return static_cast<LightKind>(i);
    return std::nullopt;
}

}  // namespace gbl
