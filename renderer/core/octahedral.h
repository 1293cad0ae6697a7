// Octahedral normal encoding: a unit vector as two numbers in [-1, 1] (the C++ twin of
// octEncode/octDecode in shaders/gbuffer_encoding.glsl; the packed layout stores it in RG16).
#pragma once

#include <glm/glm.hpp>

#include <cmath>

namespace gbl {

// Sign that maps 0 to +1, so the fold of the lower hemisphere is defined on the axes.
inline glm::vec2 signNotZero(glm::vec2 v) {
    return {v.x >= 0.0f ? 1.0f : -1.0f, v.y >= 0.0f ? 1.0f : -1.0f};
}

// Projects n onto the octahedron |x|+|y|+|z| = 1 and unfolds the lower half over the corners.
inline glm::vec2 octEncode(glm::vec3 n) {
    n /= std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
    glm::vec2 p(n.x, n.y);
    if (n.z < 0.0f) p = (glm::vec2(1.0f) - glm::abs(glm::vec2(p.y, p.x))) * signNotZero(p);
    return p;
}

inline glm::vec3 octDecode(glm::vec2 e) {
    glm::vec3 n(e.x, e.y, 1.0f - std::abs(e.x) - std::abs(e.y));
    float const t = std::max(-n.z, 0.0f);
    n.x += n.x >= 0.0f ? -t : t;
    n.y += n.y >= 0.0f ? -t : t;
    return glm::normalize(n);
}

// What an RG16 unorm target keeps of a value in [-1, 1] stored as v * 0.5 + 0.5: the nearest of
// 65536 levels, read back into [-1, 1].
inline glm::vec2 quantizeSnormAsUnorm16(glm::vec2 v) {
    glm::vec2 const u = glm::clamp(v * 0.5f + 0.5f, 0.0f, 1.0f);
    glm::vec2 const q = glm::round(u * 65535.0f) / 65535.0f;
    return q * 2.0f - 1.0f;
}

}  // namespace gbl
