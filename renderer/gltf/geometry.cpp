// Flat normals and UV-derivative tangents for glTF primitives that lack them.
#include "gltf/geometry.h"

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

namespace gbl {

namespace {

// Any unit vector perpendicular to n (n unit length).
glm::vec3 perpendicular(glm::vec3 n) {
    glm::vec3 const axis = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(axis, n));
}

bool finiteVec(glm::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

std::vector<std::uint32_t> triangleList(TriangleMode mode, std::vector<std::uint32_t> const& v) {
    std::vector<std::uint32_t> out;
    if (mode == TriangleMode::List) {
        out.assign(v.begin(), v.begin() + std::ptrdiff_t(v.size() - v.size() % 3));
        return out;
    }
    if (v.size() < 3) return out;
    out.reserve((v.size() - 2) * 3);
    for (std::size_t i = 0; i + 2 < v.size(); ++i) {
        std::uint32_t a, b, c;
        if (mode == TriangleMode::Strip) {
            a = v[i], b = v[i + 1 + i % 2], c = v[i + 2 - i % 2];
        } else {
            a = v[i + 1], b = v[i + 2], c = v[0];
        }
        if (a == b || b == c || a == c) continue;
        out.insert(out.end(), {a, b, c});
    }
    return out;
}

void generateFlatNormals(MeshData& mesh) {
    std::vector<Vertex> flat;
    flat.reserve(mesh.indices.size());
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        Vertex v[3] = {mesh.vertices[mesh.indices[t]], mesh.vertices[mesh.indices[t + 1]],
                       mesh.vertices[mesh.indices[t + 2]]};
        glm::vec3 n = glm::cross(v[1].position - v[0].position, v[2].position - v[0].position);
        float const len = glm::length(n);
        // No absolute epsilon: tiny models (Avocado is 6 cm across) have legitimately tiny areas.
        n = (len > 0.0f && std::isfinite(len)) ? n / len : glm::vec3(0, 0, 1);
        for (auto& c : v) {
            c.normal = n;
            flat.push_back(c);
        }
    }
    mesh.vertices = std::move(flat);
    mesh.indices.resize(mesh.vertices.size());
    for (std::size_t i = 0; i < mesh.indices.size(); ++i) mesh.indices[i] = std::uint32_t(i);
}

void generateTangents(MeshData& mesh, int texCoord) {
    auto uvOf = [texCoord](Vertex const& v) { return texCoord == 1 ? v.uv1 : v.uv; };
    std::vector<glm::vec3> tan(mesh.vertices.size(), glm::vec3(0.0f));
    std::vector<glm::vec3> bit(mesh.vertices.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        std::uint32_t const i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
        Vertex const &a = mesh.vertices[i0], &b = mesh.vertices[i1], &c = mesh.vertices[i2];
        glm::vec3 const e1 = b.position - a.position, e2 = c.position - a.position;
        glm::vec2 const d1 = uvOf(b) - uvOf(a), d2 = uvOf(c) - uvOf(a);
        float const det = d1.x * d2.y - d2.x * d1.y;
        if (det == 0.0f || !std::isfinite(det)) continue;
        float const r = 1.0f / det;
        glm::vec3 const dPdu = (e1 * d2.y - e2 * d1.y) * r;
        glm::vec3 const dPdv = (e2 * d1.x - e1 * d2.x) * r;
        if (!finiteVec(dPdu) || !finiteVec(dPdv)) continue;
        // Unweighted sums: each triangle's direction counts once, whatever its size.
        glm::vec3 const tu = glm::length(dPdu) > 0.0f ? glm::normalize(dPdu) : glm::vec3(0.0f);
        glm::vec3 const tv = glm::length(dPdv) > 0.0f ? glm::normalize(dPdv) : glm::vec3(0.0f);
        for (std::uint32_t i : {i0, i1, i2}) {
            tan[i] += tu;
            bit[i] += tv;
        }
    }
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        Vertex& v = mesh.vertices[i];
        glm::vec3 const n = v.normal;
        glm::vec3 t = tan[i] - n * glm::dot(n, tan[i]);  // Gram-Schmidt against the normal
        float const len = glm::length(t);
        t = (len > 1e-6f && std::isfinite(len)) ? t / len : perpendicular(n);
        // glTF's bitangent points up the image, against dP/dv (its v grows downwards), as in
        // the TANGENT data of files such as WaterBottle and Avocado.
        float const w = glm::dot(glm::cross(n, t), bit[i]) > 0.0f ? -1.0f : 1.0f;
        v.tangent = glm::vec4(t, w);
    }
}

}  // namespace gbl
