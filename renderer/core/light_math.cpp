// Radius and attenuation of point lights: the one implementation all modes and the UI use.
#include "core/light_math.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gbl {

namespace {
bool badNumber(float v) {
    return !std::isfinite(v) || v < 0.0f;
}
}  // namespace

std::optional<std::string> validateLight(PointLight const& light) {
    // Sign errors first, then non-finite positions: the order the messages always had.
    for (LightField const& f : kLightFields) {
        float const v = f.of(light);
        if (f.range == LightFieldRange::NonNegative && badNumber(v))
            return std::string("light parameter ") + std::string(f.label) + " must be a finite number >= 0 (got " +
                   std::to_string(v) + ")";
    }
    for (LightField const& f : kLightFields)
        if (f.range == LightFieldRange::Finite && !std::isfinite(f.of(light))) return "light position must be finite";
    for (LightField const& f : kLightFields) {
        float const v = f.of(light);
        if (f.range == LightFieldRange::Direction && !std::isfinite(v))
            return std::string("light parameter ") + std::string(f.label) + " must be finite (got " +
                   std::to_string(v) + ")";
        if (f.range == LightFieldRange::ConeAngle && !(v >= 0.0f && v <= kMaxSpotConeDeg))
            return std::string("light parameter ") + std::string(f.label) + " must be a number of degrees in [0, " +
                   std::to_string(int(kMaxSpotConeDeg)) + "] (got " + std::to_string(v) + ")";
    }
    if (glm::dot(light.direction, light.direction) <= 0.0f) return "light direction must not be the zero vector";
    if (light.innerConeDeg > light.outerConeDeg)
        return "light parameter inner_cone_deg must not exceed outer_cone_deg (" + std::to_string(light.innerConeDeg) +
               " > " + std::to_string(light.outerConeDeg) + ")";
    if (light.outerConeDeg <= 0.0f) return "light parameter outer_cone_deg must be greater than 0";
    for (LightField const& f : kLightFields)
        if (f.positive && f.of(light) <= 0.0f) return "light " + std::string(f.label) + " must be greater than 0";
    if (light.kc <= 0.0f && light.kl <= 0.0f && light.kq <= 0.0f)
        return "light attenuation Kc, Kl and Kq cannot all be 0 (infinite brightness at the light)";
    return std::nullopt;
}

LightFieldBounds lightFieldBounds(LightField const& f, PointLight const& l) {
    constexpr float kMax = std::numeric_limits<float>::max();
    constexpr float kTiny = std::numeric_limits<float>::denorm_min();  // the least float > 0
    switch (f.range) {
        case LightFieldRange::Finite:
        case LightFieldRange::Direction:
            return {-kMax, kMax};
        case LightFieldRange::NonNegative:
            return {f.positive ? kTiny : 0.0f, kMax};
        case LightFieldRange::ConeAngle:
            // inner <= outer, outer > 0, both within [0, kMaxSpotConeDeg].
            if (f.scalar == &PointLight::innerConeDeg) return {0.0f, l.outerConeDeg};
            return {std::max(l.innerConeDeg, kTiny), kMaxSpotConeDeg};
    }
    return {-kMax, kMax};
}

LightRadius solveLightRadius(float imax, float kc, float kl, float kq, float threshold) {
    if (badNumber(imax) || badNumber(kc) || badNumber(kl) || badNumber(kq) || badNumber(threshold) || threshold <= 0.0f)
        return {0.0f, RadiusKind::Zero};
    // Solve in double: Imax/threshold can be large and the quadratic formula cancels badly.
    double const c = double(kc) - double(imax) / double(threshold);
    if (c >= 0.0) return {0.0f, RadiusKind::Zero};
    if (kq > 0.0f) {
        double const a = kq, b = kl;
        // Numerically stable positive root: 2c / (-b - sqrt(b^2 - 4ac)), c < 0 so the root is real.
        double const disc = b * b - 4.0 * a * c;
        double const root = (2.0 * c) / (-b - std::sqrt(disc));
        if (root > kLightRadiusCap) return {kLightRadiusCap, RadiusKind::Capped};
        return {float(root), RadiusKind::Quadratic};
    }
    if (kl > 0.0f) {
        double const root = -c / double(kl);
        if (root > kLightRadiusCap) return {kLightRadiusCap, RadiusKind::Capped};
        return {float(root), RadiusKind::Linear};
    }
    return {kLightRadiusCap, RadiusKind::Capped};
}

LightRadius lightRadius(PointLight const& light) {
    if (validateLight(light)) return {0.0f, RadiusKind::Zero};
    return solveLightRadius(lightImax(light), light.kc, light.kl, light.kq, light.threshold);
}

SpotCone spotCone(PointLight const& light) {
    if (light.kind != LightKind::Spot) return {};
    float const cosOuter = std::cos(glm::radians(light.outerConeDeg));
    float const cosInner = std::cos(glm::radians(light.innerConeDeg));
    return {cosOuter, 1.0f / std::max(cosInner - cosOuter, kSpotMinCosDelta)};
}

float attenuationCutoff(PointLight const& light, float radius) {
    if (light.kl > 0.0f || light.kq > 0.0f) return attenuation(light.kc, light.kl, light.kq, radius);
    float const imax = lightImax(light);
    return imax > 0.0f ? light.threshold / imax : 0.0f;
}

float windowedAttenuation(PointLight const& light, float radius, float d) {
    if (!(d < radius)) return 0.0f;
    float const att = attenuation(light.kc, light.kl, light.kq, d);
    return std::max(att - attenuationCutoff(light, radius), 0.0f);
}

}  // namespace gbl
