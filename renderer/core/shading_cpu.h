// The lighting equation of docs/lighting.md on the CPU: the pixel inspector's per-light
// breakdown and the reference the GL tests compare the shaders against.
#pragma once

#include "core/light_math.h"
#include "core/pipeline_settings.h"
#include "core/point_light.h"

#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace gbl {

struct ShadingInputs {
    glm::vec3 position{0.0f};            // world-space surface point
    glm::vec3 normal{0.0f, 1.0f, 0.0f};  // unit
    glm::vec3 albedo{1.0f};
    float specular = 0.5f;
    glm::vec3 viewPosition{0.0f};
    float shininess = 32.0f;
    glm::vec3 emissive{0.0f};  // emitted radiance, added once (not per light)
    float occlusion = 1.0f;    // ambient occlusion: scales the ambient term only
    // The equation (docs/lighting.md), and for the learnopengl one whether the mode cuts it at the
    // radius (cutsAtRadius): shadingOf fills both from the pipeline's settings.
    ShadingModel model = ShadingModel::GbufferLab;
    bool cutAtRadius = false;
};

// The settings' shininess and equation, as the frame's mode applies it.
inline void shadingOf(PipelineSettings const& settings, ShadingInputs& s) {
    s.shininess = settings.shininess;
    s.model = settings.shading;
    s.cutAtRadius = cutsAtRadius(settings);
}

struct LightContribution {
    int lightIndex = -1;
    float distance = 0.0f;
    float radius = 0.0f;
    float attenuation = 0.0f;  // as applied: windowed, or classic with learnopengl (1 for directional lights)
    float cone = 1.0f;         // spot cone factor (1 for point and directional lights)
    glm::vec3 diffuse{0.0f};   // albedo * N.L * colour * intensity * attenuation * cone
    glm::vec3 specular{0.0f};  // specular * (N.H)^shininess * colour * intensity * attenuation * cone
    bool reaches() const { return attenuation > 0.0f && cone > 0.0f; }
    glm::vec3 total() const { return diffuse + specular; }
};

// Blinn-Phong of one light of any kind (docs/lighting.md): directional lights come from
// -direction with attenuation 1; spots multiply the point light's terms by the cone factor.
inline LightContribution shadeLightCpu(PointLight const& light, ShadingInputs const& s) {
    LightContribution c;
    glm::vec3 L;
    if (light.kind == LightKind::Directional) {
        if (validateLight(light)) return c;  // an invalid light shades nothing, as lightRadius() says
        c.attenuation = 1.0f;
        L = -lightDirection(light);
    } else {
        c.radius = lightRadius(light).radius;
        glm::vec3 const toLight = light.position - s.position;
        c.distance = glm::length(toLight);
        bool const classic = s.model == ShadingModel::LearnOpenGl;
        // A light of radius 0 (too dim to reach the threshold, or invalid) shades nothing in either.
        bool const cut = c.radius <= 0.0f || (s.cutAtRadius && c.distance >= c.radius);
        c.attenuation = !classic ? windowedAttenuation(light, c.radius, c.distance)
                        : cut    ? 0.0f
                                 : attenuation(light.kc, light.kl, light.kq, c.distance);
        if (c.attenuation <= 0.0f || c.distance <= 0.0f) return c;
        L = toLight / c.distance;
        c.cone = spotConeFactor(spotCone(light), glm::dot(-L, lightDirection(light)));
        if (c.cone <= 0.0f) return c;
    }
    glm::vec3 const V = glm::normalize(s.viewPosition - s.position);
    glm::vec3 const H = glm::normalize(L + V);
    float const diff = std::max(glm::dot(s.normal, L), 0.0f);
    // LearnOpenGL's shader does not gate the specular term by N.L: a light behind the surface can
    // still add a highlight where N.H > 0.
    bool const gated = s.model == ShadingModel::GbufferLab;
    float const spec = diff > 0.0f || !gated ? std::pow(std::max(glm::dot(s.normal, H), 0.0f), s.shininess) : 0.0f;
    glm::vec3 const radiance = light.color * light.intensity * (c.attenuation * c.cone);
    c.diffuse = s.albedo * diff * radiance;
    c.specular = glm::vec3(s.specular * spec) * radiance;
    return c;
}

// The light-independent part (shaders/surface_terms.glsl): ambient * albedo * occlusion + emissive.
inline glm::vec3 surfaceTermsCpu(ShadingInputs const& s, glm::vec3 ambient) {
    return ambient * s.albedo * s.occlusion + s.emissive;
}

// The surface terms plus every light that reaches the point; `contributions` (optional) receives
// the lights that reach the point (non-zero attenuation and cone factor), in list order.
inline glm::vec3 shadePointCpu(std::span<PointLight const> lights, ShadingInputs const& s, glm::vec3 ambient,
                               std::vector<LightContribution>* contributions = nullptr) {
    glm::vec3 color = surfaceTermsCpu(s, ambient);
    for (std::size_t i = 0; i < lights.size(); ++i) {
        LightContribution c = shadeLightCpu(lights[i], s);
        if (!c.reaches()) continue;
        c.lightIndex = int(i);
        color += c.total();
        if (contributions) contributions->push_back(c);
    }
    return color;
}

}  // namespace gbl
