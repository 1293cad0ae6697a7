// The samples of one MSAA pixel as plain values (docs/msaa.md): how many distinct surfaces they
// hold under the edges strategy's thresholds. The CPU twin of shaders/msaa_edges.glsl, which asks
// the same of the GPU (msaaComplexPixel: more than one?; msaaDistinctSurfaces: how many, the
// editor's samples-that-differ heat map); tests compare the two.
#pragma once

#include "core/msaa.h"

#include <glm/glm.hpp>

#include <cmath>
#include <span>
#include <vector>

namespace gbl {

// One sample as the lighting decodes it (Renderer::readMsaaDecodedSample): position (w = 1 where
// drawn), normal, albedo + specular.
struct MsaaSampleValues {
    glm::vec4 position{0.0f};
    glm::vec4 normal{0.0f};
    glm::vec4 albedoSpec{0.0f};
};

// Whether sample b holds the same surface as sample a by msaa_edges.glsl's test (a plays sample 0):
// both background, or both drawn with b near a's tangent plane (along it is the pixel's own extent,
// over which the layouts that rebuild position spread their samples) and normals and albedo within
// the thresholds.
inline bool msaaSameSurface(MsaaSampleValues const& a, MsaaSampleValues const& b, glm::vec3 eye,
                            MsaaThresholds const& t = kMsaaThresholds) {
    bool const drawnA = a.position.w != 0.0f, drawnB = b.position.w != 0.0f;
    if (drawnA != drawnB) return false;
    if (!drawnA) return true;
    float const reach = t.relativeDistance * glm::length(glm::vec3(a.position) - eye);
    // The decoded normals are unit already; normalising again keeps hand-made values honest.
    glm::vec3 const na = glm::normalize(glm::vec3(a.normal)), nb = glm::normalize(glm::vec3(b.normal));
    if (std::abs(glm::dot(glm::vec3(b.position) - glm::vec3(a.position), na)) > reach) return false;
    if (glm::dot(nb, na) < t.normalCos) return false;
    glm::vec4 const d = glm::abs(b.albedoSpec - a.albedoSpec);
    return std::fmax(std::fmax(d.r, d.g), std::fmax(d.b, d.a)) <= t.albedo;
}

// How many distinct surfaces the samples of a pixel hold, 1..samples (0 for none): each sample
// joins the first earlier distinct one it matches (msaaSameSurface with that one first), or starts
// a new one. It is 1 exactly where msaa_edges.glsl finds the pixel simple: a sample that differs
// from sample 0 starts a second surface.
inline int msaaDistinctSamples(std::span<MsaaSampleValues const> samples, glm::vec3 eye,
                               MsaaThresholds const& t = kMsaaThresholds) {
    std::vector<std::size_t> firsts;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        bool joined = false;
        for (std::size_t f : firsts)
            if (msaaSameSurface(samples[f], samples[i], eye, t)) {
                joined = true;
                break;
            }
        if (!joined) firsts.push_back(i);
    }
    return int(firsts.size());
}

}  // namespace gbl
