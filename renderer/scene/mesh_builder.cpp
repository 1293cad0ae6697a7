// Procedural mesh builders: every shape is a parametric grid through one surface helper.
#include "scene/mesh_builder.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace gbl {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Builds a vertex from a position, a normal and the two surface derivatives. The tangent is
// made orthogonal to the normal here, once, so callers can pass rough directions.
Vertex surfaceVertex(glm::vec3 p, glm::vec3 n, glm::vec2 uv, glm::vec3 dPdu, glm::vec3 dPdv) {
    n = glm::normalize(n);
    glm::vec3 const t = glm::normalize(dPdu - n * glm::dot(n, dPdu));
    float const w = glm::dot(glm::cross(n, t), dPdv) < 0.0f ? -1.0f : 1.0f;
    return {p, n, uv, glm::vec4(t, w)};
}

// Adds one triangle, wound counter-clockwise about its vertices' normals; zero-area triangles
// (the collapsed rows at a sphere's poles or a disc's centre) are dropped.
void addTriangle(MeshData& m, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    glm::vec3 const pa = m.vertices[a].position, pb = m.vertices[b].position, pc = m.vertices[c].position;
    glm::vec3 const g = glm::cross(pb - pa, pc - pa);
    if (glm::dot(g, g) <= 1e-20f) return;
    glm::vec3 const n = m.vertices[a].normal + m.vertices[b].normal + m.vertices[c].normal;
    if (glm::dot(g, n) < 0.0f) std::swap(b, c);
    m.indices.insert(m.indices.end(), {a, b, c});
}

// A (nu + 1) x (nv + 1) grid of vertices from vertexAt(i, j), split into triangles.
template <class F>
void addSurface(MeshData& m, int nu, int nv, F&& vertexAt) {
    auto const base = std::uint32_t(m.vertices.size());
    for (int j = 0; j <= nv; ++j)
        for (int i = 0; i <= nu; ++i) m.vertices.push_back(vertexAt(i, j));
    auto const row = std::uint32_t(nu + 1);
    for (int j = 0; j < nv; ++j) {
        for (int i = 0; i < nu; ++i) {
            std::uint32_t const a = base + std::uint32_t(j) * row + std::uint32_t(i);
            addTriangle(m, a, a + 1, a + row + 1);
            addTriangle(m, a, a + row + 1, a + row);
        }
    }
}

// A flat quad corner + s*eu + t*ev (s, t in 0..1) with the given outward normal; u runs along
// eu and v along ev, both in world units times uvScale.
void addQuad(MeshData& m, glm::vec3 corner, glm::vec3 eu, glm::vec3 ev, glm::vec3 normal, float uvScale) {
    float const lu = glm::length(eu), lv = glm::length(ev);
    addSurface(m, 1, 1, [&](int i, int j) {
        return surfaceVertex(corner + float(i) * eu + float(j) * ev, normal,
                             glm::vec2(float(i) * lu, float(j) * lv) * uvScale, eu, ev);
    });
}

// cos and sin of 2*pi*i/n (or pi*i/n for half turns), with the end points exact so that
// seams and poles meet without cracks.
glm::vec2 circlePoint(int i, int n, bool halfTurn = false) {
    int const period = halfTurn ? 2 * n : n;
    int const k = ((i % period) + period) % period;
    if (k == 0) return {1.0f, 0.0f};
    if (2 * k == period) return {-1.0f, 0.0f};
    double const a = 2.0 * std::numbers::pi * double(k) / double(period);
    return {float(std::cos(a)), float(std::sin(a))};
}

}  // namespace

MeshData makeBox(glm::vec3 size, float uvScale) {
    MeshData m;
    m.name = "box";
    glm::vec3 const h = size * 0.5f;
    glm::vec3 const X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
    // Side faces: u to the right, v downwards, seen from outside.
    addQuad(m, {-h.x, h.y, h.z}, X * size.x, -Y * size.y, Z, uvScale);    // +Z
    addQuad(m, {h.x, h.y, -h.z}, -X * size.x, -Y * size.y, -Z, uvScale);  // -Z
    addQuad(m, {h.x, h.y, h.z}, -Z * size.z, -Y * size.y, X, uvScale);    // +X
    addQuad(m, {-h.x, h.y, -h.z}, Z * size.z, -Y * size.y, -X, uvScale);  // -X
    addQuad(m, {-h.x, h.y, -h.z}, X * size.x, Z * size.z, Y, uvScale);    // +Y: u = +X, v = +Z
    addQuad(m, {-h.x, -h.y, h.z}, X * size.x, -Z * size.z, -Y, uvScale);  // -Y
    return m;
}

MeshData makePlane(glm::vec2 size, int segX, int segZ, float uvScale) {
    MeshData m;
    m.name = "plane";
    segX = std::max(segX, 1);
    segZ = std::max(segZ, 1);
    glm::vec2 const h = size * 0.5f;
    addSurface(m, segX, segZ, [&](int i, int j) {
        float const x = -h.x + size.x * float(i) / float(segX), z = -h.y + size.y * float(j) / float(segZ);
        return surfaceVertex({x, 0.0f, z}, {0, 1, 0}, glm::vec2(x + h.x, z + h.y) * uvScale, {1, 0, 0}, {0, 0, 1});
    });
    return m;
}

namespace {

// Disc of radius r at height y facing up (+Y) or down, planar UVs like a box's caps.
void addDisc(MeshData& m, float r, float y, bool up, int segments, float uvScale) {
    addSurface(m, segments, 1, [&](int i, int j) {
        glm::vec2 const c = circlePoint(i, segments);
        float const rr = j == 0 ? r : 0.0f;
        glm::vec3 const p(rr * c.y, y, rr * c.x);
        glm::vec3 const dv = up ? glm::vec3(0, 0, 1) : glm::vec3(0, 0, -1);
        return surfaceVertex(p, {0, up ? 1.0f : -1.0f, 0}, glm::vec2(p.x + r, glm::dot(p, dv) + r) * uvScale, {1, 0, 0},
                             dv);
    });
}

}  // namespace

MeshData makeCylinder(float radius, float height, int segments, int rings, float uvScale, bool caps) {
    MeshData m;
    m.name = "cylinder";
    segments = std::max(segments, 3);
    rings = std::max(rings, 1);
    float const circumference = 2.0f * kPi * radius;
    // Angle 0 faces +Z and grows towards +X, so u runs to the right seen from outside.
    addSurface(m, segments, rings, [&](int i, int j) {
        glm::vec2 const c = circlePoint(i, segments);
        float const v = float(j) / float(rings);
        glm::vec3 const n(c.y, 0.0f, c.x);
        glm::vec3 const p(radius * c.y, height * (1.0f - v), radius * c.x);
        return surfaceVertex(p, n, glm::vec2(circumference * float(i) / float(segments), height * v) * uvScale,
                             {c.x, 0.0f, -c.y}, {0, -1, 0});
    });
    if (caps) {
        addDisc(m, radius, height, true, segments, uvScale);
        addDisc(m, radius, 0.0f, false, segments, uvScale);
    }
    return m;
}

MeshData makeArch(float innerRadius, float outerRadius, float depth, int segments, float uvScale, bool squareOuter) {
    MeshData m;
    m.name = "arch";
    segments = std::max(4, (segments + 3) / 4 * 4);
    float const ri = innerRadius, ro = outerRadius, hz = depth * 0.5f;
    // Outline points at the i-th angle step (0 at +X, segments at -X).
    auto inner = [&](int i) { return circlePoint(i, segments, true) * ri; };
    auto outer = [&](int i) -> glm::vec2 {
        glm::vec2 const c = circlePoint(i, segments, true);
        if (!squareOuter) return c * ro;
        if (4 * i <= segments) return {ro, 4 * i == segments ? ro : ro * c.y / c.x};
        if (4 * i >= 3 * segments) return {-ro, 4 * i == 3 * segments ? ro : ro * c.y / -c.x};
        return {ro * c.x / c.y, ro};
    };
    // Front (+Z) and back (-Z) faces: planar UVs, u to the right and v downwards seen from outside.
    for (int side = 0; side < 2; ++side) {
        float const s = side == 0 ? 1.0f : -1.0f;
        addSurface(m, segments, 1, [&](int i, int j) {
            glm::vec2 const q = j == 0 ? inner(i) : outer(i);
            glm::vec3 const p(q.x, q.y, s * hz);
            return surfaceVertex(p, {0, 0, s}, glm::vec2(s * q.x + ro, ro - q.y) * uvScale, {s, 0, 0}, {0, -1, 0});
        });
    }
    // Intrados (the underside of the arch): normals point towards the arch's centre; u follows
    // the curve from the +X foot, v runs along Z from front to back.
    addSurface(m, segments, 1, [&](int i, int j) {
        glm::vec2 const c = circlePoint(i, segments, true);
        float const z = j == 0 ? hz : -hz;
        return surfaceVertex({ri * c.x, ri * c.y, z}, {-c.x, -c.y, 0},
                             glm::vec2(ri * kPi * float(i) / float(segments), hz - z) * uvScale, {-c.y, c.x, 0},
                             {0, 0, -1});
    });
    if (squareOuter) {
        glm::vec3 const X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
        addQuad(m, {-ro, ro, -hz}, X * (2.0f * ro), Z * depth, Y, uvScale);  // top
        addQuad(m, {ro, ro, hz}, -Z * depth, -Y * ro, X, uvScale);           // +X side
        addQuad(m, {-ro, ro, -hz}, Z * depth, -Y * ro, -X, uvScale);         // -X side
    } else {
        addSurface(m, segments, 1, [&](int i, int j) {
            glm::vec2 const c = circlePoint(i, segments, true);
            float const z = j == 0 ? hz : -hz;
            return surfaceVertex({ro * c.x, ro * c.y, z}, {c.x, c.y, 0},
                                 glm::vec2(ro * kPi * float(i) / float(segments), hz - z) * uvScale, {-c.y, c.x, 0},
                                 {0, 0, -1});
        });
    }
    // The two feet, facing down.
    glm::vec3 const X(1, 0, 0), Z(0, 0, 1), down(0, -1, 0);
    addQuad(m, {ri, 0, hz}, X * (ro - ri), -Z * depth, down, uvScale);
    addQuad(m, {-ro, 0, hz}, X * (ro - ri), -Z * depth, down, uvScale);
    return m;
}

MeshData makeSphere(float radius, int slices, int stacks, float uvScale) {
    MeshData m;
    m.name = "sphere";
    slices = std::max(slices, 3);
    stacks = std::max(stacks, 2);
    float const circumference = 2.0f * kPi * radius;
    addSurface(m, slices, stacks, [&](int i, int j) {
        glm::vec2 const lon = circlePoint(i, slices);
        glm::vec2 const lat = circlePoint(j, stacks, true);  // (cos, sin) of the angle from the pole
        glm::vec3 const n(lat.y * lon.y, lat.x, lat.y * lon.x);
        // The east direction is well defined even at the poles, where dP/du vanishes.
        return surfaceVertex(
            radius * n, n,
            glm::vec2(circumference * float(i) / float(slices), 0.5f * circumference * float(j) / float(stacks)) *
                uvScale,
            {lon.x, 0.0f, -lon.y}, {lat.x * lon.y, -lat.y, lat.x * lon.x});
    });
    return m;
}

MeshData makeTorus(float majorRadius, float minorRadius, int majorSegments, int minorSegments, float uvScale) {
    MeshData m;
    m.name = "torus";
    majorSegments = std::max(majorSegments, 3);
    minorSegments = std::max(minorSegments, 3);
    addSurface(m, majorSegments, minorSegments, [&](int i, int j) {
        glm::vec2 const a = circlePoint(i, majorSegments);
        glm::vec2 const b = circlePoint(j, minorSegments);
        glm::vec3 const out(a.y, 0.0f, a.x);
        glm::vec3 const n = b.x * out + b.y * glm::vec3(0, 1, 0);
        glm::vec3 const p = majorRadius * out + minorRadius * n;
        glm::vec3 const dPdv = -b.y * out + b.x * glm::vec3(0, 1, 0);
        return surfaceVertex(p, n,
                             glm::vec2(2.0f * kPi * majorRadius * float(i) / float(majorSegments),
                                       2.0f * kPi * minorRadius * float(j) / float(minorSegments)) *
                                 uvScale,
                             {a.x, 0.0f, -a.y}, dPdv);
    });
    return m;
}

void transformMesh(MeshData& mesh, glm::mat4 const& m) {
    glm::mat3 const linear(m);
    glm::mat3 const normalMatrix = glm::inverseTranspose(linear);
    bool const mirrored = glm::determinant(linear) < 0.0f;
    for (auto& v : mesh.vertices) {
        v.position = glm::vec3(m * glm::vec4(v.position, 1.0f));
        v.normal = glm::normalize(normalMatrix * v.normal);
        glm::vec3 t = linear * glm::vec3(v.tangent);
        t = glm::normalize(t - v.normal * glm::dot(v.normal, t));
        v.tangent = glm::vec4(t, mirrored ? -v.tangent.w : v.tangent.w);
    }
    if (mirrored)
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
            std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
}

void appendMesh(MeshData& dst, MeshData const& src, glm::mat4 const& m) {
    MeshData copy = src;
    transformMesh(copy, m);
    auto const base = std::uint32_t(dst.vertices.size());
    dst.vertices.insert(dst.vertices.end(), copy.vertices.begin(), copy.vertices.end());
    dst.indices.reserve(dst.indices.size() + copy.indices.size());
    for (auto i : copy.indices) dst.indices.push_back(base + i);
}

}  // namespace gbl
