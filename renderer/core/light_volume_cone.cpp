// Building the spot lights' volume cone and placing it.
#include "core/light_volume_cone.h"

#include "core/light_math.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace gbl {

ConeMesh makeLightVolumeCone(int slices) {
    if (slices < 3)
        throw std::invalid_argument("makeLightVolumeCone(): needs slices >= 3, got " + std::to_string(slices));
    ConeMesh m;
    m.slices = slices;
    m.positions.emplace_back(0.0f, 0.0f, 0.0f);
    for (int j = 0; j < slices; ++j) {
        float const phi = 2.0f * glm::pi<float>() * float(j) / float(slices);
        m.positions.emplace_back(std::cos(phi), std::sin(phi), 1.0f);
    }
    m.positions.emplace_back(0.0f, 0.0f, 1.0f);
    auto const apex = std::uint32_t(0), centre = std::uint32_t(slices + 1);
    auto ring = [slices](int j) { return std::uint32_t(1 + j % slices); };
    for (int j = 0; j < slices; ++j) {
        // phi grows counter-clockwise seen from +Z (the base's outside): the base keeps that
        // order, the sides (seen from outside, across the axis) take the other.
        m.triangles.insert(m.triangles.end(), {apex, ring(j + 1), ring(j)});
        m.triangles.insert(m.triangles.end(), {centre, ring(j), ring(j + 1)});
        m.lines.insert(m.lines.end(), {apex, ring(j), ring(j), ring(j + 1)});
    }
    return m;
}

float coneRadialScale(ConeMesh const& mesh) {
    // Each side face meets the base plane z = 1 along its ring edge: the closest such line to the
    // axis sets how far in the polygon cuts.
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
        glm::dvec3 const a(mesh.positions[mesh.triangles[t]]), b(mesh.positions[mesh.triangles[t + 1]]),
            c(mesh.positions[mesh.triangles[t + 2]]);
        if (a != glm::dvec3(0.0)) continue;  // side faces start at the apex
        glm::dvec2 const e = glm::dvec2(c) - glm::dvec2(b);
        double const len = glm::length(e);
        if (len < 1e-12) continue;
        best = std::min(best, std::abs(b.x * e.y - b.y * e.x) / len);
    }
    // The same relative margin as the sphere's enclosingScale.
    return float((1.0 / best) * (1.0 + 1e-6));
}

VolumeShape volumeShape(PointLight const& light) {
    if (!isLocalLight(light)) return VolumeShape::None;
    if (light.kind == LightKind::Spot && light.outerConeDeg <= kConeVolumeMaxOuterDeg) return VolumeShape::Cone;
    return VolumeShape::Sphere;
}

void coneBasis(glm::vec3 axis, glm::vec3& x, glm::vec3& y) {
    glm::vec3 const helper = std::abs(axis.y) < 0.99f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    x = glm::normalize(glm::cross(helper, axis));
    y = glm::cross(axis, x);
}

ConeVolume coneVolume(PointLight const& light, float radius, float radialScale, float scale) {
    ConeVolume c;
    c.apex = light.position;
    c.axis = lightDirection(light);
    c.height = radius * scale;
    c.ringRadius = c.height * std::tan(glm::radians(light.outerConeDeg)) * radialScale;
    return c;
}

glm::vec3 coneVertexToWorld(ConeVolume const& cone, glm::vec3 unit) {
    glm::vec3 x, y;
    coneBasis(cone.axis, x, y);
    return cone.apex + (x * unit.x + y * unit.y) * cone.ringRadius + cone.axis * (unit.z * cone.height);
}

namespace {
float segmentDistance(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    glm::vec2 const ab = b - a;
    float const t = std::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-30f), 0.0f, 1.0f);
    return glm::length(p - (a + t * ab));
}
}  // namespace

bool coneMayContainCamera(glm::vec3 eye, ConeVolume const& cone, float nearCornerDistance) {
    // In the plane through the axis and the eye: a = along the axis, b = away from it. The solid
    // cone is the triangle (0,0), (h,0), (h,R) turned about the axis.
    glm::vec3 const v = eye - cone.apex;
    float const a = glm::dot(v, cone.axis);
    float const b = glm::length(v - a * cone.axis);
    float const h = cone.height, r = cone.ringRadius;
    if (a >= 0.0f && a <= h && b * h <= a * r) return true;  // inside
    float const d = std::min(segmentDistance({a, b}, {0.0f, 0.0f}, {h, r}), segmentDistance({a, b}, {h, 0.0f}, {h, r}));
    return d < nearCornerDistance;
}

ArrowMesh makeDirectionArrow() {
    ArrowMesh a;
    a.positions = {{0.0f, 0.0f, 0.0f},    {0.0f, 0.0f, 1.0f},   {0.12f, 0.0f, 0.75f},
                   {-0.12f, 0.0f, 0.75f}, {0.0f, 0.12f, 0.75f}, {0.0f, -0.12f, 0.75f}};
    a.lines = {0, 1, 1, 2, 1, 3, 1, 4, 1, 5};
    return a;
}

}  // namespace gbl
