// A point light as the editor, the renderer and session files see it, and the table of its numbers.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <string>
#include <string_view>

namespace gbl {

// Cut-off brightness used by the classic texts: a light is "dark enough" below 5/256.
inline constexpr float kDefaultLightThreshold = 5.0f / 256.0f;

// Most lights any scene, session or command accepts; more are refused with this number.
inline constexpr int kMaxLights = 262144;

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

// What validateLight() demands of a number.
enum class LightFieldRange {
    Finite,       // any finite value (position)
    NonNegative,  // finite and >= 0 (colour, intensity, attenuation, threshold)
};

// One editable number of a light: a float member or one component of a vec3 member.
struct LightField {
    std::string_view name;   // the UI script's name: x y z r g b intensity kc kl kq threshold
    std::string_view label;  // the name in error sentences: "position.x", "color.r", "Kc"
    LightFieldRange range;
    float PointLight::*scalar = nullptr;
    glm::vec3 PointLight::*vector = nullptr;
    int component = 0;

    float& of(PointLight& l) const { return scalar ? l.*scalar : (l.*vector)[component]; }
    float of(PointLight const& l) const { return scalar ? l.*scalar : (l.*vector)[component]; }
};

// Every number of PointLight, once: validateLight() checks these and the UI script's `light` and
// `expect-light` commands read and write them. tests/light_math_test.cpp fails to compile when
// PointLight gains a member (a structured binding of all members) and fails when an entry does
// not change the light it edits.
inline constexpr std::array<LightField, 11> kLightFields{{
    {"x", "position.x", LightFieldRange::Finite, nullptr, &PointLight::position, 0},
    {"y", "position.y", LightFieldRange::Finite, nullptr, &PointLight::position, 1},
    {"z", "position.z", LightFieldRange::Finite, nullptr, &PointLight::position, 2},
    {"r", "color.r", LightFieldRange::NonNegative, nullptr, &PointLight::color, 0},
    {"g", "color.g", LightFieldRange::NonNegative, nullptr, &PointLight::color, 1},
    {"b", "color.b", LightFieldRange::NonNegative, nullptr, &PointLight::color, 2},
    {"intensity", "intensity", LightFieldRange::NonNegative, &PointLight::intensity},
    {"kc", "Kc", LightFieldRange::NonNegative, &PointLight::kc},
    {"kl", "Kl", LightFieldRange::NonNegative, &PointLight::kl},
    {"kq", "Kq", LightFieldRange::NonNegative, &PointLight::kq},
    {"threshold", "threshold", LightFieldRange::NonNegative, &PointLight::threshold},
}};

// The entry of kLightFields called `name`, or nullptr.
inline LightField const* findLightField(std::string_view name) {
    for (LightField const& f : kLightFields)
        if (f.name == name) return &f;
    return nullptr;
}

}  // namespace gbl
