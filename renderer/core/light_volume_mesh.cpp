// Building the light-volume sphere and measuring how far its faces cut into the true sphere.
#include "core/light_volume_mesh.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace gbl {

SphereMesh makeLightVolumeSphere(int stacks, int slices) {
    if (stacks < 2 || slices < 3)
        throw std::invalid_argument("makeLightVolumeSphere(): needs stacks >= 2 and slices >= 3, got " +
                                    std::to_string(stacks) + " x " + std::to_string(slices));
    SphereMesh m;
    m.stacks = stacks;
    m.slices = slices;
    float const pi = glm::pi<float>();

    m.positions.emplace_back(0.0f, 1.0f, 0.0f);
    for (int i = 1; i < stacks; ++i) {
        float const theta = pi * float(i) / float(stacks);  // from the north pole
        for (int j = 0; j < slices; ++j) {
            float const phi = 2.0f * pi * float(j) / float(slices);
            m.positions.emplace_back(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
        }
    }
    m.positions.emplace_back(0.0f, -1.0f, 0.0f);

    auto const north = std::uint32_t(0);
    auto const south = std::uint32_t(m.positions.size() - 1);
    auto ring = [slices](int i, int j) { return std::uint32_t(1 + (i - 1) * slices + (j % slices)); };

    // Winding: phi grows from +X towards +Z, which seen from outside (above, at +Y) turns
    // clockwise; so a CCW-from-outside triangle goes against growing phi.
    for (int j = 0; j < slices; ++j) {
        // North cap.
        m.triangles.insert(m.triangles.end(), {north, ring(1, j + 1), ring(1, j)});
        // Bands between ring i and ring i + 1.
        for (int i = 1; i < stacks - 1; ++i) {
            std::uint32_t const a = ring(i, j), b = ring(i, j + 1), c = ring(i + 1, j), d = ring(i + 1, j + 1);
            m.triangles.insert(m.triangles.end(), {a, b, d, a, d, c});
        }
        // South cap.
        m.triangles.insert(m.triangles.end(), {south, ring(stacks - 1, j), ring(stacks - 1, j + 1)});
    }

    for (int j = 0; j < slices; ++j) {
        // Meridian from pole to pole.
        m.lines.insert(m.lines.end(), {north, ring(1, j)});
        for (int i = 1; i < stacks - 1; ++i) m.lines.insert(m.lines.end(), {ring(i, j), ring(i + 1, j)});
        m.lines.insert(m.lines.end(), {ring(stacks - 1, j), south});
        // Ring edges.
        for (int i = 1; i < stacks; ++i) m.lines.insert(m.lines.end(), {ring(i, j), ring(i, j + 1)});
    }
    return m;
}

float minFacePlaneDistance(std::span<glm::vec3 const> positions, std::span<std::uint32_t const> triangles) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
        // Double precision: the normals of thin pole triangles lose digits in float.
        glm::dvec3 const a(positions[triangles[t]]), b(positions[triangles[t + 1]]), c(positions[triangles[t + 2]]);
        glm::dvec3 const n = glm::cross(b - a, c - a);
        double const len = glm::length(n);
        if (len < 1e-12) continue;
        best = std::min(best, std::abs(glm::dot(n / len, a)));
    }
    return float(best);
}

float enclosingScale(SphereMesh const& mesh) {
    double const d = minFacePlaneDistance(mesh.positions, mesh.triangles);
    // A relative margin of 1e-6 (about 8 float ulps) so that the float rounding of vertices
    // multiplied by scale and radius never pulls a face inside the sphere.
    return float((1.0 / d) * (1.0 + 1e-6));
}

}  // namespace gbl
