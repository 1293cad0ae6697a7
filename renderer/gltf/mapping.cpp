// glTF-to-scene mappings for materials, lights and the initial camera (docs/gltf.md).
#include "gltf/mapping.h"

#include "core/light_math.h"

#include <algorithm>
#include <cmath>

namespace gbl {

float specularFromMetallicRoughness(float metallic, float roughness, float dielectricWeight) {
    auto const sane = [](float v, float fallback) { return std::isfinite(v) ? v : fallback; };
    float const m = std::clamp(sane(metallic, 0.0f), 0.0f, 1.0f);
    float const r = std::clamp(sane(roughness, 1.0f), 0.0f, 1.0f);
    float const w = std::max(sane(dielectricWeight, 1.0f), 0.0f);
    float const gloss = (1.0f - r) * (1.0f - r);
    float const base = 0.5f * w + (1.0f - 0.5f * w) * m;  // mix(0.5 * w, 1, m)
    return std::clamp(gloss * base, 0.0f, 1.0f);
}

PointLight pointLightWithRadius(glm::vec3 position, glm::vec3 color, float intensity, float radius, std::string name) {
    PointLight light;
    light.position = position;
    light.color = color;
    light.intensity = intensity;
    light.kc = 1.0f;
    light.kl = 0.0f;
    light.name = std::move(name);
    // Kq R^2 + Kc = Imax / threshold at the radius R.
    double const ratio = double(lightImax(light)) / double(light.threshold);
    if (ratio > 1.0 && radius > 0.0f && std::isfinite(radius))
        light.kq = float((ratio - 1.0) / (double(radius) * double(radius)));
    else
        light.kq = 1.0f;
    return light;
}

std::optional<PointLight> pointLightFromGltf(glm::vec3 position, glm::vec3 color, float intensityCandela, float range,
                                             std::string name, std::string* why) {
    auto fail = [&](std::string reason) -> std::optional<PointLight> {
        if (why) *why = std::move(reason);
        return std::nullopt;
    };
    if (!std::isfinite(intensityCandela) || intensityCandela < 0.0f)
        return fail("its intensity is negative or not a finite number");
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(color[i]) || color[i] < 0.0f)
            return fail("its colour has a negative or non-finite component");
        if (!std::isfinite(position[i])) return fail("its node transform places it at a non-finite position");
    }
    if (!std::isfinite(range) || range < 0.0f) return fail("its range is negative or not a finite number");
    glm::vec3 const c = glm::min(color, glm::vec3(1.0f));
    float const intensity = intensityCandela * kGltfCandelaToIntensity;
    if (range > 0.0f) return pointLightWithRadius(position, c, intensity, range, std::move(name));
    PointLight light;
    light.position = position;
    light.color = c;
    light.intensity = intensity;
    light.kc = 1.0f;
    light.kl = 0.0f;
    light.kq = 1.0f;
    light.name = std::move(name);
    return light;
}

std::vector<PointLight> generateLightsForBounds(Bounds const& bounds) {
    glm::vec3 const c = bounds.center();
    float r = bounds.radius();
    if (!(r > 0.0f) || !std::isfinite(r)) r = 1.0f;
    std::vector<PointLight> lights;
    // Key lights: 1.5 r from the centre, reaching 6 r so the far side of the scene is still lit.
    for (int i = 0; i < 4; ++i) {
        float const a = glm::radians(45.0f + 90.0f * float(i));
        glm::vec3 const dir = glm::normalize(glm::vec3(std::cos(a), 0.8f, std::sin(a)));
        lights.push_back(pointLightWithRadius(c + dir * (1.5f * r), glm::vec3(1.0f, 0.96f, 0.9f), 1.0f, 6.0f * r,
                                              "key " + std::to_string(i + 1)));
    }
    // Fill lights on a golden-angle spiral through the bounds: evenly spread, no random numbers,
    // so the same file always gets the same lights.
    glm::vec3 const half = (bounds.max - bounds.min) * 0.5f;
    glm::vec3 const extent = glm::max(half, glm::vec3(0.1f * r));
    int const n = 12;
    for (int i = 0; i < n; ++i) {
        float const t = (float(i) + 0.5f) / float(n);
        float const y = 1.0f - 2.0f * t;
        float const ring = std::sqrt(std::max(0.0f, 1.0f - y * y));
        float const phi = 2.39996323f * float(i);  // golden angle
        glm::vec3 const p = c + extent * 1.1f * glm::vec3(std::cos(phi) * ring, y, std::sin(phi) * ring);
        float const hue = std::fmod(float(i) * 0.618034f, 1.0f) * 6.0f;
        glm::vec3 const rgb =
            glm::clamp(glm::vec3(std::abs(hue - 3.0f) - 1.0f, 2.0f - std::abs(hue - 2.0f), 2.0f - std::abs(hue - 4.0f)),
                       0.0f, 1.0f);
        lights.push_back(pointLightWithRadius(p, glm::mix(rgb, glm::vec3(1.0f), 0.25f), 1.0f, 0.8f * r,
                                              "fill " + std::to_string(i + 1)));
    }
    return lights;
}

Camera frameBounds(Bounds const& bounds, float fovYDegrees) {
    glm::vec3 const c = bounds.center();
    float r = bounds.radius();
    if (!(r > 0.0f) || !std::isfinite(r)) r = 1.0f;
    Camera cam;
    cam.fovYDegrees = fovYDegrees;
    float const dist = 1.1f * r / std::sin(glm::radians(fovYDegrees) * 0.5f);
    float const elevation = glm::radians(20.0f);
    cam.position = c + dist * glm::vec3(0.0f, std::sin(elevation), std::cos(elevation));
    cam.lookAt(c);
    // Room to orbit and fly out; near/far ratio of 2000 keeps 24-bit depth precise enough.
    cam.farPlane = (dist + r) * 8.0f;
    cam.nearPlane = cam.farPlane / 2000.0f;
    return cam;
}

Camera cameraFromGltf(glm::mat4 const& world, float yfovRadians, float znear, float zfar, float fallbackFar) {
    Camera cam;
    cam.position = glm::vec3(world[3]);
    glm::vec3 const axis = glm::mat3(world) * glm::vec3(0.0f, 0.0f, -1.0f);
    float const len = glm::length(axis);
    glm::vec3 const forward = (len > 0.0f && std::isfinite(len)) ? axis / len : glm::vec3(0.0f, 0.0f, -1.0f);
    cam.yawDegrees = glm::degrees(std::atan2(forward.z, forward.x));
    // Straight up or down leaves no horizon to orient the view by; the editor's rig stops at 89 too.
    cam.pitchDegrees = std::clamp(glm::degrees(std::asin(std::clamp(forward.y, -1.0f, 1.0f))), -89.0f, 89.0f);
    cam.fovYDegrees = glm::degrees(yfovRadians);
    cam.nearPlane = znear;
    cam.farPlane = zfar > znear ? zfar : std::max(fallbackFar, znear * 2000.0f);
    return cam;
}

}  // namespace gbl
