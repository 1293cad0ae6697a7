// The glTF scene builder's meshes: one MeshData per triangle primitive (lists, strips and fans, plain or
// Draco-compressed), with checked attributes and indices.
#include "gltf/scene_builder_parts.h"

#include "gltf/draco.h"
#include "gltf/geometry.h"
#include "gltf/mapping.h"

#include <climits>
#include <cmath>

namespace gbl::gltf {

namespace {

// The attributes the loader reads, with their components per element.
std::map<std::string, int> const kAttributeComponents = {
    {"POSITION", 3}, {"NORMAL", 3}, {"TEXCOORD_0", 2}, {"TEXCOORD_1", 2}, {"TANGENT", 4}};

}  // namespace

// The primitive's KHR_draco_mesh_compression object, or null.
Json const* SceneBuilder::dracoExtension(int meshIndex, std::size_t primitive, std::string const& who) {
    Json const* meshes = member(doc_, "meshes");
    if (!meshes || std::size_t(meshIndex) >= meshes->size()) return nullptr;
    Json const* prims = member((*meshes)[std::size_t(meshIndex)], "primitives");
    if (!prims || primitive >= prims->size()) return nullptr;
    Json const* ext = member((*prims)[primitive], "extensions");
    Json const* draco = ext ? member(*ext, "KHR_draco_mesh_compression") : nullptr;
    if (draco) requireKind(*draco, Kind::Object, who + "'s KHR_draco_mesh_compression");
    return draco;
}

std::optional<DracoPrimitive> SceneBuilder::decodeDraco(Json const& ext, tinygltf::Primitive const& prim,
                                                        std::string const& who) {
    Json const* view = member(ext, "bufferView");
    Json const* attrs = member(ext, "attributes");
    if (!view || !attrs) fail(who + "'s KHR_draco_mesh_compression needs a bufferView and attributes");
    requireKind(*view, Kind::Index, who + "'s KHR_draco_mesh_compression.bufferView");
    requireKind(*attrs, Kind::Object, who + "'s KHR_draco_mesh_compression.attributes");
    std::map<std::string, int> ids;
    for (auto it = attrs->begin(); it != attrs->end(); ++it) {
        requireKind(*it, Kind::Index, who + "'s Draco attribute " + printable(it.key(), 40));
        ids[it.key()] = int(std::min<std::uint64_t>(it->get<std::uint64_t>(), INT_MAX));
    }
    if (!gltfDecodesDraco()) {
        // Not required by the file: its accessors may carry uncompressed data as well.
        auto const pos = prim.attributes.find("POSITION");
        bool const fallback = pos != prim.attributes.end() && pos->second >= 0 &&
                              std::size_t(pos->second) < model_.accessors.size() &&
                              model_.accessors[std::size_t(pos->second)].bufferView >= 0;
        if (fallback) {
            scene_.warnings.push_back(who + " is Draco-compressed and " + kNoDracoReason +
                                      "; its uncompressed copy is loaded");
            return std::nullopt;
        }
    }
    int const bv = int(std::min<std::uint64_t>(view->get<std::uint64_t>(), INT_MAX));
    return decodeDracoPrimitive(reader_.bufferView(bv, who + "'s Draco data"), ids, kAttributeComponents, who,
                                options_);
}

std::vector<int> SceneBuilder::buildMesh(int meshIndex) {
    auto const& mesh = model_.meshes[std::size_t(meshIndex)];
    std::vector<int> parts;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        auto const& prim = mesh.primitives[p];
        std::string const who = "mesh " + std::to_string(meshIndex) + " primitive " + num(p);
        TriangleMode mode = TriangleMode::List;
        if (prim.mode == TINYGLTF_MODE_TRIANGLE_STRIP)
            mode = TriangleMode::Strip;
        else if (prim.mode == TINYGLTF_MODE_TRIANGLE_FAN)
            mode = TriangleMode::Fan;
        else if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) {
            static constexpr char const* kModes[] = {"points", "lines", "line loops", "line strips"};
            std::string const what = prim.mode >= 0 && prim.mode <= 3 ? kModes[prim.mode] : "an unknown mode";
            scene_.warnings.push_back(who + " draws " + what +
                                      "; only triangles (lists, strips and fans) are loaded, so it is skipped");
            continue;
        }
        std::optional<DracoPrimitive> draco;
        if (Json const* ext = dracoExtension(meshIndex, p, who)) draco = decodeDraco(*ext, prim, who);
        auto attr = [&](char const* name) {
            auto it = prim.attributes.find(name);
            return it == prim.attributes.end() ? -1 : it->second;
        };
        // An attribute's values: decoded from Draco when the extension holds it, else its accessor.
        auto read = [&](char const* name, int accessor) {
            if (draco)
                if (auto it = draco->attributes.find(name); it != draco->attributes.end()) return it->second;
            return reader_.read(accessor, who + " " + name, kAttributeComponents.at(name));
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

        std::vector<double> const pos = read("POSITION", posAccessor);
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
            std::vector<double> const v = read("NORMAL", a);
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
        for (int set : {0, 1}) {
            std::string const name = "TEXCOORD_" + std::to_string(set);
            int const a = attr(name.c_str());
            if (a < 0) continue;
            std::vector<double> const v = read(name.c_str(), a);
            sameCount(v, 2, name.c_str());
            bool bad = false;
            for (std::size_t i = 0; i < n; ++i) {
                glm::vec2 uv = glm::vec2(float(v[2 * i]), float(v[2 * i + 1]));
                if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = glm::vec2(0.0f), bad = true;
                (set == 0 ? out.vertices[i].uv : out.vertices[i].uv1) = uv;
            }
            if (bad) scene_.warnings.push_back(who + " has non-finite " + name + " values; they are set to 0");
        }
        if (attr("TEXCOORD_1") < 0 && out.material >= 0) {
            Material const& m = scene_.materials[std::size_t(out.material)];
            if (m.baseColorTransform.texCoord == 1 || m.normalTransform.texCoord == 1 ||
                m.specularTransform.texCoord == 1) {
                scene_.warnings.push_back(who +
                                          "'s material reads TEXCOORD_1, which the primitive lacks; "
                                          "TEXCOORD_0 is used");
                for (auto& v : out.vertices) v.uv1 = v.uv;
            }
        }
        bool haveTangents = false;
        if (int a = attr("TANGENT"); a >= 0 && haveNormals) {
            std::vector<double> const v = read("TANGENT", a);
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

        std::vector<std::uint32_t> sequence;
        if (draco) {
            // Draco stores triangles; the primitive's mode and indices describe the same list.
            sequence = std::move(draco->indices);
            mode = TriangleMode::List;
        } else if (prim.indices >= 0) {
            auto const& acc = model_.accessors.at(std::size_t(prim.indices));  // range checked by tinygltf
            if (acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
                fail(who + "'s indices are not unsigned 8, 16 or 32-bit integers");
            std::vector<double> const idx = reader_.read(prim.indices, who + " indices", 1);
            sequence.resize(idx.size());
            for (std::size_t i = 0; i < idx.size(); ++i) {
                if (idx[i] >= double(n))
                    fail(who + " has index " + std::to_string(std::uint64_t(idx[i])) + " at position " + num(i) +
                         ", but only " + num(n) + " vertices");
                sequence[i] = std::uint32_t(idx[i]);
            }
        } else {
            sequence.resize(n);
            for (std::size_t i = 0; i < n; ++i) sequence[i] = std::uint32_t(i);
        }
        if (mode == TriangleMode::List && sequence.size() % 3 != 0)
            scene_.warnings.push_back(who + " has " + num(sequence.size()) +
                                      " indices, not a multiple of 3; the incomplete triangle is dropped");
        out.indices = triangleList(mode, sequence);
        uniqueTriangles_ += out.indices.size() / 3;
        if (uniqueTriangles_ > options_.maxTriangles)
            fail("it has more than the limit of " + num(options_.maxTriangles) + " triangles");
        if (out.indices.empty()) {
            scene_.warnings.push_back(who + " has no triangles; skipped");
            continue;
        }
        if (!haveNormals) generateFlatNormals(out);
        bool const normalMapped = prim.material >= 0 && scene_.materials[std::size_t(out.material)].normalTexture >= 0;
        if (normalMapped && !haveTangents)
            generateTangents(out, scene_.materials[std::size_t(out.material)].normalTransform.texCoord);
        scene_.meshes.push_back(std::move(out));
        parts.push_back(int(scene_.meshes.size() - 1));
    }
    return parts;
}

}  // namespace gbl::gltf
