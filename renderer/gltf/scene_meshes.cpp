// The glTF scene builder's meshes: one MeshData per triangle primitive, with checked attributes and indices.
#include "gltf/scene_builder_parts.h"

#include "gltf/geometry.h"
#include "gltf/mapping.h"

#include <cmath>

namespace gbl::gltf {

std::vector<int> SceneBuilder::buildMesh(int meshIndex) {
    auto const& mesh = model_.meshes[std::size_t(meshIndex)];
    std::vector<int> parts;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        auto const& prim = mesh.primitives[p];
        std::string const who = "mesh " + std::to_string(meshIndex) + " primitive " + num(p);
        if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) {
            static constexpr char const* kModes[] = {"points",    "lines",           "line loops",   "line strips",
                                                     "triangles", "triangle strips", "triangle fans"};
            std::string const mode = prim.mode >= 0 && prim.mode <= 6 ? kModes[prim.mode] : "an unknown mode";
            scene_.warnings.push_back(who + " draws " + mode + "; only triangle lists are loaded, so it is skipped");
            continue;
        }
        auto attr = [&](char const* name) {
            auto it = prim.attributes.find(name);
            return it == prim.attributes.end() ? -1 : it->second;
        };
        int const posAccessor = attr("POSITION");
        if (posAccessor < 0) {
            scene_.warnings.push_back(who + " has no POSITION attribute; skipped");
            continue;
        }
        MeshData out;
        out.name = (mesh.name.empty() ? "mesh " + std::to_string(meshIndex) : mesh.name) +
                   (mesh.primitives.size() > 1 ? " #" + num(p) : "");
        out.material = prim.material >= 0 ? material(prim.material) : -1;

        std::vector<double> const pos = reader_.read(posAccessor, who + " POSITION", 3);
        std::size_t const n = pos.size() / 3;
        for (std::size_t i = 0; i < pos.size(); ++i)
            if (!std::isfinite(float(pos[i]))) fail(who + " has a NaN or infinite position at vertex " + num(i / 3));
        out.vertices.resize(n);
        for (std::size_t i = 0; i < n; ++i)
            out.vertices[i].position = glm::vec3(float(pos[3 * i]), float(pos[3 * i + 1]), float(pos[3 * i + 2]));

        auto sameCount = [&](std::vector<double> const& v, int comps, char const* what) {
            if (v.size() / std::size_t(comps) != n)
                fail(who + " has " + num(v.size() / std::size_t(comps)) + " " + what + " values for " + num(n) +
                     " positions");
        };
        bool haveNormals = false;
        if (int a = attr("NORMAL"); a >= 0) {
            std::vector<double> const v = reader_.read(a, who + " NORMAL", 3);
            sameCount(v, 3, "NORMAL");
            haveNormals = true;
            for (std::size_t i = 0; i < n && haveNormals; ++i) {
                glm::vec3 const nn = glm::vec3(float(v[3 * i]), float(v[3 * i + 1]), float(v[3 * i + 2]));
                float const len = glm::length(nn);
                if (!(len > 0.0f) || !std::isfinite(len))
                    haveNormals = false;
                else
                    out.vertices[i].normal = nn / len;
            }
            if (!haveNormals) scene_.warnings.push_back(who + " has zero or non-finite normals; flat normals are used");
        }
        if (int a = attr("TEXCOORD_0"); a >= 0) {
            std::vector<double> const v = reader_.read(a, who + " TEXCOORD_0", 2);
            sameCount(v, 2, "TEXCOORD_0");
            bool bad = false;
            for (std::size_t i = 0; i < n; ++i) {
                glm::vec2 uv = glm::vec2(float(v[2 * i]), float(v[2 * i + 1]));
                if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = glm::vec2(0.0f), bad = true;
                out.vertices[i].uv = uv;
            }
            if (bad) scene_.warnings.push_back(who + " has non-finite texture coordinates; they are set to 0");
        }
        bool haveTangents = false;
        if (int a = attr("TANGENT"); a >= 0 && haveNormals) {
            std::vector<double> const v = reader_.read(a, who + " TANGENT", 4);
            sameCount(v, 4, "TANGENT");
            haveTangents = true;
            for (std::size_t i = 0; i < n && haveTangents; ++i) {
                glm::vec3 const t = glm::vec3(float(v[4 * i]), float(v[4 * i + 1]), float(v[4 * i + 2]));
                float const len = glm::length(t);
                if (!(len > 0.0f) || !std::isfinite(len) || !std::isfinite(float(v[4 * i + 3])))
                    haveTangents = false;
                else
                    out.vertices[i].tangent = glm::vec4(t / len, v[4 * i + 3] < 0.0 ? -1.0f : 1.0f);
            }
            if (!haveTangents) scene_.warnings.push_back(who + " has zero or non-finite tangents; they are generated");
        }

        if (prim.indices >= 0) {
            auto const& acc = model_.accessors.at(std::size_t(prim.indices));  // range checked by tinygltf
            if (acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
                fail(who + "'s indices are not unsigned 8, 16 or 32-bit integers");
            std::vector<double> const idx = reader_.read(prim.indices, who + " indices", 1);
            out.indices.resize(idx.size());
            for (std::size_t i = 0; i < idx.size(); ++i) {
                if (idx[i] >= double(n))
                    fail(who + " has index " + std::to_string(std::uint64_t(idx[i])) + " at position " + num(i) +
                         ", but only " + num(n) + " vertices");
                out.indices[i] = std::uint32_t(idx[i]);
            }
        } else {
            out.indices.resize(n);
            for (std::size_t i = 0; i < n; ++i) out.indices[i] = std::uint32_t(i);
        }
        if (out.indices.size() % 3 != 0) {
            scene_.warnings.push_back(who + " has " + num(out.indices.size()) +
                                      " indices, not a multiple of 3; the incomplete triangle is dropped");
            out.indices.resize(out.indices.size() - out.indices.size() % 3);
        }
        uniqueTriangles_ += out.indices.size() / 3;
        if (uniqueTriangles_ > options_.maxTriangles)
            fail("it has more than the limit of " + num(options_.maxTriangles) + " triangles");
        if (out.indices.empty()) {
            scene_.warnings.push_back(who + " has no triangles; skipped");
            continue;
        }
        if (!haveNormals) generateFlatNormals(out);
        bool const normalMapped = prim.material >= 0 && scene_.materials[std::size_t(out.material)].normalTexture >= 0;
        if (normalMapped && !haveTangents) generateTangents(out);
        scene_.meshes.push_back(std::move(out));
        parts.push_back(int(scene_.meshes.size() - 1));
    }
    return parts;
}

}  // namespace gbl::gltf
