// Pure light math shared by the renderer, the editor's plots and the tests (no GL here).
#pragma once

#include "core/point_light.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace gbl {

// Radius used when a light never falls below its threshold (Kl = Kq = 0).
inline constexpr float kLightRadiusCap = 1000.0f;

enum class RadiusKind {
    Quadratic,  // positive root of Kq d^2 + Kl d + Kc - Imax/threshold = 0
    Linear,     // Kq = 0: d = (Imax/threshold - Kc) / Kl
    Capped,     // Kl = Kq = 0 (never falls off) or the root lies past kLightRadiusCap: radius is the cap
    Zero,       // Imax <= threshold * Kc: never bright enough to matter, skipped
};

struct LightRadius {
    float radius = 0.0f;
    RadiusKind kind = RadiusKind::Zero;
};

// Brightest component of the light: the value that has to fall to the threshold.
inline float lightImax(PointLight const& light) {
    return light.intensity * std::max({light.color.r, light.color.g, light.color.b});
}

// Classic attenuation factor 1 / (Kc + Kl d + Kq d^2).
inline float attenuation(float kc, float kl, float kq, float d) {
    return 1.0f / (kc + kl * d + kq * d * d);
}

// Point and spot lights are local (a radius, a volume, tile lists); directional lights are global:
// every mode shades them in its full-screen loop (docs/lighting.md, "Light kinds").
inline bool isLocalLight(PointLight const& light) {
    return light.kind != LightKind::Directional;
}

// Unit vector from a surface towards a directional light, or along which a spot shines.
inline glm::vec3 lightDirection(PointLight const& light) {
    return glm::normalize(light.direction);
}

// Smallest cos(inner) - cos(outer) the cone factor divides by: inner == outer gives a hard edge
// instead of a division by zero.
inline constexpr float kSpotMinCosDelta = 1e-4f;

// The cone of a spot as the shaders take it: factor = saturate((cos(angle) - cosOuter) * scale)^2,
// scale = 1 / max(cos(inner) - cos(outer), kSpotMinCosDelta). Squared, as KHR_lights_punctual's
// sample implementation does: the edge fades in smoothly. Other kinds get cosOuter = -2 and
// scale = 1, which gives 1 for every angle (no cone), with no branch in the shaders.
struct SpotCone {
    float cosOuter = -2.0f;
    float scale = 1.0f;
};
SpotCone spotCone(PointLight const& light);

// Cone factor at the angle whose cosine is `cosAngle` (between the spot's axis and the
// direction from the light to the surface).
inline float spotConeFactor(SpotCone cone, float cosAngle) {
    float const t = std::clamp((cosAngle - cone.cosOuter) * cone.scale, 0.0f, 1.0f);
    return t * t;
}

// Returns an error sentence when a parameter is NaN, infinite or negative, else nullopt.
std::optional<std::string> validateLight(PointLight const& light);

// Distance at which Imax * attenuation(d) == threshold. Invalid lights give kind Zero.
LightRadius solveLightRadius(float imax, float kc, float kl, float kq, float threshold);
LightRadius lightRadius(PointLight const& light);

// The same light with its falloff stretched by `scale` in space: Kl / scale and Kq / scale^2,
// so attenuation(d * scale) of the result equals attenuation(d) of the original and the radius
// scales by exactly `scale` (the bench's --radius-scale). scale must be > 0.
inline PointLight scaleLightFalloff(PointLight light, float scale) {
    light.kl /= scale;
    light.kq /= scale * scale;
    return light;
}

// The attenuation subtracted by the window: the classic factor's value at the radius, so the
// window is continuous there even when the radius was capped. Lights that never fall off
// (Kl = Kq = 0) subtract threshold / Imax instead, since subtracting their constant factor
// would leave nothing; they alone end with a step at the cap.
float attenuationCutoff(PointLight const& light, float radius);

// The attenuation actually applied by every lighting mode: the classic factor minus its
// value at the radius, so that the contribution reaches exactly zero at the radius and stays
// zero past it (docs/lighting.md, "Windowed attenuation").
float windowedAttenuation(PointLight const& light, float radius, float d);

}  // namespace gbl
