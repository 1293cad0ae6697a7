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

// Which kinds of light use a field (bit i for LightKind i).
inline constexpr unsigned kAllLightKinds = 0x7u;
inline constexpr unsigned kSpotAndDirectional =
    (1u << unsigned(LightKind::Spot)) | (1u << unsigned(LightKind::Directional));
inline constexpr unsigned kSpotOnly = 1u << unsigned(LightKind::Spot);

// One editable number of a light: a float member or one component of a vec3 member.
struct LightField {
    std::string_view name;   // the UI script's name: x y z r g b kc kl kq intensity threshold dx dy dz inner outer
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
    // The Lights panel: the row the field is drawn on (the fields of a row share it, a vector's
    // three components are one widget), the number's format, the drag speed's floor (model/drag_speed.h:
    // the speed follows the value, over several decades when `logDrag`), the kinds that use it, and
    // the tooltip.
    std::string_view row;
    std::string_view format = "%.3f";
    float dragStep = 1e-3f;
    bool logDrag = false;
    unsigned kinds = kAllLightKinds;
    std::string_view help;

    float& of(PointLight& l) const { return scalar ? l.*scalar : (l.*vector)[component]; }
    float of(PointLight const& l) const { return scalar ? l.*scalar : (l.*vector)[component]; }
    bool usedBy(LightKind k) const { return (kinds >> unsigned(k)) & 1u; }
};

// Every number of PointLight, once: validateLight() checks these, session files and G-buffer
// manifests read and write them (core/json_fields.h), the UI script's `light` and `expect-light`
// commands read and write them, and the Lights panel draws them with the bounds lightFieldBounds()
// gives. tests/light_math_test.cpp fails to compile when PointLight gains a member (a structured
// binding of all members) and fails when an entry does not change the light it edits. `kind` is not
// a number: the script's `light N kind NAME` and the panel's combo set it.
inline constexpr std::array<LightField, 16> kLightFields{{
    {.name = "x",
     .label = "position.x",
     .range = LightFieldRange::Finite,
     .vector = &PointLight::position,
     .component = 0,
     .fileKey = "position",
     .row = "Position",
     .dragStep = 0.01f,
     .help = "world position; a directional light's only sets where its arrow is drawn"},
    {.name = "y",
     .label = "position.y",
     .range = LightFieldRange::Finite,
     .vector = &PointLight::position,
     .component = 1,
     .fileKey = "position",
     .row = "Position",
     .dragStep = 0.01f,
     .help = "world position"},
    {.name = "z",
     .label = "position.z",
     .range = LightFieldRange::Finite,
     .vector = &PointLight::position,
     .component = 2,
     .fileKey = "position",
     .row = "Position",
     .dragStep = 0.01f,
     .help = "world position"},
    {.name = "r",
     .label = "color.r",
     .range = LightFieldRange::NonNegative,
     .vector = &PointLight::color,
     .component = 0,
     .fileKey = "color",
     .row = "Colour",
     .help = "linear RGB, multiplied by the intensity"},
    {.name = "g",
     .label = "color.g",
     .range = LightFieldRange::NonNegative,
     .vector = &PointLight::color,
     .component = 1,
     .fileKey = "color",
     .row = "Colour",
     .help = "linear RGB"},
    {.name = "b",
     .label = "color.b",
     .range = LightFieldRange::NonNegative,
     .vector = &PointLight::color,
     .component = 2,
     .fileKey = "color",
     .row = "Colour",
     .help = "linear RGB"},
    {.name = "kc",
     .label = "Kc",
     .range = LightFieldRange::NonNegative,
     .scalar = &PointLight::kc,
     .fileKey = "kc",
     .row = "Atten.",
     .format = "Kc %.3f",
     .dragStep = 1e-3f,
     .logDrag = true,
     .help = "constant term of Kc + Kl d + Kq d^2"},
    {.name = "kl",
     .label = "Kl",
     .range = LightFieldRange::NonNegative,
     .scalar = &PointLight::kl,
     .fileKey = "kl",
     .row = "Atten.",
     .format = "Kl %.4f",
     .dragStep = 1e-4f,
     .logDrag = true,
     .help = "linear term of Kc + Kl d + Kq d^2"},
    {.name = "kq",
     .label = "Kq",
     .range = LightFieldRange::NonNegative,
     .scalar = &PointLight::kq,
     .fileKey = "kq",
     .row = "Atten.",
     .format = "Kq %.5f",
     .dragStep = 1e-5f,
     .logDrag = true,
     .help = "quadratic term of Kc + Kl d + Kq d^2"},
    {.name = "intensity",
     .label = "intensity",
     .range = LightFieldRange::NonNegative,
     .scalar = &PointLight::intensity,
     .fileKey = "intensity",
     .row = "I, cut",
     .format = "I %.3f",
     .help = "multiplies the colour: Imax = intensity * max(colour)"},
    {.name = "threshold",
     .label = "threshold",
     .range = LightFieldRange::NonNegative,
     .scalar = &PointLight::threshold,
     .fileKey = "threshold",
     .positive = true,
     .row = "I, cut",
     .format = "cut %.5f",
     .dragStep = 1e-5f,
     .help = "brightness below which the light counts as dark (5/256 by default); sets the radius"},
    {.name = "dx",
     .label = "direction.x",
     .range = LightFieldRange::Direction,
     .vector = &PointLight::direction,
     .component = 0,
     .fileKey = "direction",
     .optionalInFiles = true,
     .row = "Dir",
     .dragStep = 0.01f,
     .kinds = kSpotAndDirectional,
     .help = "where the light shines (normalised when shading; not all zero)"},
    {.name = "dy",
     .label = "direction.y",
     .range = LightFieldRange::Direction,
     .vector = &PointLight::direction,
     .component = 1,
     .fileKey = "direction",
     .optionalInFiles = true,
     .row = "Dir",
     .dragStep = 0.01f,
     .kinds = kSpotAndDirectional,
     .help = "where the light shines"},
    {.name = "dz",
     .label = "direction.z",
     .range = LightFieldRange::Direction,
     .vector = &PointLight::direction,
     .component = 2,
     .fileKey = "direction",
     .optionalInFiles = true,
     .row = "Dir",
     .dragStep = 0.01f,
     .kinds = kSpotAndDirectional,
     .help = "where the light shines"},
    {.name = "inner",
     .label = "inner_cone_deg",
     .range = LightFieldRange::ConeAngle,
     .scalar = &PointLight::innerConeDeg,
     .fileKey = "inner_cone_deg",
     .optionalInFiles = true,
     .row = "Cone",
     .format = "in %.1f deg",
     .dragStep = 0.25f,
     .kinds = kSpotOnly,
     .help = "half-angle of full light around the direction, degrees"},
    {.name = "outer",
     .label = "outer_cone_deg",
     .range = LightFieldRange::ConeAngle,
     .scalar = &PointLight::outerConeDeg,
     .fileKey = "outer_cone_deg",
     .optionalInFiles = true,
     .row = "Cone",
     .format = "out %.1f deg",
     .dragStep = 0.25f,
     .kinds = kSpotOnly,
     .help = "half-angle where the light ends, degrees (at most 90)"},
}};

// The values an edit of `f` may take on `l` with its other numbers kept: validateLight() accepts
// every value in [lo, hi] and refuses every value outside, but for the rules over several fields
// (a direction not all zero; Kc, Kl and Kq not all zero), which its message names. The Lights panel's drags use these
// bounds, so the panel, the script and files accept the same numbers. An unbounded side is +-FLT_MAX.
struct LightFieldBounds {
    float lo, hi;
};
LightFieldBounds lightFieldBounds(LightField const& f, PointLight const& l);

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
