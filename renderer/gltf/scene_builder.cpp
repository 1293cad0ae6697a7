// The glTF loader's scene builder: node hierarchy, meshes, materials, images and lights.
#include "gltf/scene_builder.h"

#include "gltf/accessors.h"
#include "gltf/geometry.h"
#include "gltf/images.h"
#include "gltf/mapping.h"
#include "core/light_math.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <climits>
#include <cmath>
#include <optional>
#include <set>
#include <utility>

namespace gbl::gltf {

namespace {

glm::mat4 localTransform(tinygltf::Node const& n, std::size_t index) {
    std::string const who = "node " + num(index);
    if (!n.matrix.empty()) {
        if (n.matrix.size() != 16) fail(who + "'s matrix has " + num(n.matrix.size()) + " numbers; expected 16");
        glm::mat4 m;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) m[c][r] = float(n.matrix[std::size_t(c * 4 + r)]);
        return m;
    }
    auto check = [&](std::vector<double> const& v, std::size_t want, char const* what) {
        if (!v.empty() && v.size() != want)
            fail(who + "'s " + what + " has " + num(v.size()) + " numbers; expected " + num(want));
    };
    check(n.translation, 3, "translation");
    check(n.rotation, 4, "rotation");
    check(n.scale, 3, "scale");
    glm::mat4 m(1.0f);
    if (!n.translation.empty())
        m = glm::translate(m, glm::vec3(float(n.translation[0]), float(n.translation[1]), float(n.translation[2])));
    if (!n.rotation.empty()) {
        glm::quat q(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2]));
        float const len = glm::length(q);
        m *= (len > 0.0f && std::isfinite(len)) ? glm::mat4_cast(q / len) : glm::mat4(1.0f);
    }
    if (!n.scale.empty()) m = glm::scale(m, glm::vec3(float(n.scale[0]), float(n.scale[1]), float(n.scale[2])));
    return m;
}

bool finiteMatrix(glm::mat4 const& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

class SceneBuilder {
public:
    SceneBuilder(tinygltf::Model const& model, Json const& doc, ImageStash& stash, GltfLoadOptions const& options,
                 Progress& progress)
        : model_(model), doc_(doc), stash_(stash), options_(options), progress_(progress), reader_(model, options) {}

    SceneData build() {
        std::vector<std::pair<int, glm::mat4>> const placed = placeNodes();

        // Materials first: their images dominate the time, and primitives need to know about normal maps.
        std::set<int> usedMaterials;
        for (auto const& [node, world] : placed) {
            int const meshIndex = model_.nodes[std::size_t(node)].mesh;
            if (meshIndex < 0) continue;
            if (std::size_t(meshIndex) >= model_.meshes.size())
                fail("node " + std::to_string(node) + " refers to mesh " + std::to_string(meshIndex) + ", but the file has " +
                     num(model_.meshes.size()));
            for (auto const& prim : model_.meshes[std::size_t(meshIndex)].primitives) {
                if (prim.material >= 0 && std::size_t(prim.material) >= model_.materials.size())
                    fail("mesh " + std::to_string(meshIndex) + " refers to material " + std::to_string(prim.material) +
                         ", but the file has " + num(model_.materials.size()));
                if (prim.material >= 0) usedMaterials.insert(prim.material);
            }
        }
        imagesToDecode_ = countImages(usedMaterials);
        progress_.report(0.1f, "decoding images");
        for (int m : usedMaterials) material(m);

        progress_.report(0.6f, "building meshes");
        std::map<int, std::vector<int>> meshParts;  // glTF mesh -> our meshes (one per primitive)
        std::size_t drawn = 0;
        std::size_t done = 0;
        for (auto const& [node, world] : placed) {
            int const meshIndex = model_.nodes[std::size_t(node)].mesh;
            if (meshIndex < 0) continue;
            auto it = meshParts.find(meshIndex);
            if (it == meshParts.end()) {
                it = meshParts.emplace(meshIndex, buildMesh(meshIndex)).first;
                progress_.report(0.6f + 0.3f * float(++done) / float(std::max<std::size_t>(placed.size(), 1)),
                                 "building meshes");
            }
            for (int part : it->second) {
                drawn += scene_.meshes[std::size_t(part)].indices.size() / 3;
                if (drawn > options_.maxTriangles)
                    fail("its instances draw more than the limit of " + num(options_.maxTriangles) + " triangles");
                scene_.instances.push_back({part, world});
            }
        }

        progress_.report(0.95f, "lights and camera");
        addLights(placed);
        Bounds const bounds = scene_.bounds();
        if (scene_.instances.empty()) scene_.warnings.push_back("the scene has no triangles to draw");
        if (scene_.lights.empty()) scene_.lights = generateLightsForBounds(bounds);
        scene_.camera = frameBounds(bounds);
        return std::move(scene_);
    }

private:
    // Validates the node graph (a forest: in-range children, one parent each, no cycles) and
    // returns the nodes of the chosen scene with their world matrices.
    std::vector<std::pair<int, glm::mat4>> placeNodes() {
        std::size_t const n = model_.nodes.size();
        std::vector<int> parent(n, -1);
        for (std::size_t i = 0; i < n; ++i) {
            for (int c : model_.nodes[i].children) {
                if (c < 0 || std::size_t(c) >= n)
                    fail("node " + num(i) + " lists child " + std::to_string(c) + ", but the file has " + num(n) + " nodes");
                if (std::size_t(c) == i) fail("node " + num(i) + " is its own child (the node graph is recursive)");
                if (parent[std::size_t(c)] >= 0)
                    fail("node " + std::to_string(c) + " has two parents (nodes " + std::to_string(parent[std::size_t(c)]) +
                         " and " + num(i) + "); glTF node graphs must be trees");
                parent[std::size_t(c)] = int(i);
            }
        }
        // With one parent each, a cycle is a chain of parents that comes back on itself.
        std::vector<char> state(n, 0);  // 0 unvisited, 1 on the current chain, 2 known acyclic
        for (std::size_t start = 0; start < n; ++start) {
            std::vector<int> chain;
            int cur = int(start);
            while (cur >= 0 && state[std::size_t(cur)] == 0) {
                state[std::size_t(cur)] = 1;
                chain.push_back(cur);
                cur = parent[std::size_t(cur)];
            }
            if (cur >= 0 && state[std::size_t(cur)] == 1)
                fail("node " + std::to_string(cur) + " is its own ancestor (the node graph is recursive)");
            for (int c : chain) state[std::size_t(c)] = 2;
        }

        std::vector<int> roots;
        if (!model_.scenes.empty()) {
            int s = model_.defaultScene;
            if (s < 0) s = 0;
            if (std::size_t(s) >= model_.scenes.size())
                fail("its default scene is " + std::to_string(s) + ", but the file has " + num(model_.scenes.size()));
            roots = model_.scenes[std::size_t(s)].nodes;
        } else {
            for (std::size_t i = 0; i < n; ++i)
                if (parent[i] < 0) roots.push_back(int(i));
        }
        std::vector<std::pair<int, glm::mat4>> placed;
        std::vector<char> visited(n, 0);
        std::vector<std::pair<int, glm::mat4>> stack;
        for (auto it = roots.rbegin(); it != roots.rend(); ++it) {
            if (*it < 0 || std::size_t(*it) >= n)
                fail("the scene lists node " + std::to_string(*it) + ", but the file has " + num(n) + " nodes");
            stack.push_back({*it, glm::mat4(1.0f)});
        }
        while (!stack.empty()) {
            auto const [node, parentWorld] = stack.back();
            stack.pop_back();
            if (visited[std::size_t(node)]) {
                scene_.warnings.push_back("node " + std::to_string(node) + " is reached twice from the scene; drawn once");
                continue;
            }
            visited[std::size_t(node)] = 1;
            glm::mat4 const world = parentWorld * localTransform(model_.nodes[std::size_t(node)], std::size_t(node));
            if (!finiteMatrix(world)) fail("node " + std::to_string(node) + " has a NaN or infinite transform");
            placed.push_back({node, world});
            auto const& children = model_.nodes[std::size_t(node)].children;
            for (auto c = children.rbegin(); c != children.rend(); ++c) stack.push_back({*c, world});
        }
        return placed;
    }

    // --- images and materials -----------------------------------------------------------

    int textureSource(int texture, std::string const& who) {
        if (texture < 0) return -1;
        if (std::size_t(texture) >= model_.textures.size())
            fail(who + " refers to texture " + std::to_string(texture) + ", but the file has " + num(model_.textures.size()));
        int const source = model_.textures[std::size_t(texture)].source;
        if (source < 0) {
            scene_.warnings.push_back(who + " uses texture " + std::to_string(texture) +
                                      ", which has no image this loader can read; ignored");
            return -1;
        }
        if (std::size_t(source) >= model_.images.size())
            fail("texture " + std::to_string(texture) + " refers to image " + std::to_string(source) + ", but the file has " +
                 num(model_.images.size()));
        return source;
    }

    std::size_t countImages(std::set<int> const& materials) {
        std::set<int> images;
        for (int m : materials) {
            auto const& mat = model_.materials[std::size_t(m)];
            std::string const who = "material " + std::to_string(m);
            for (int t : {mat.pbrMetallicRoughness.baseColorTexture.index, mat.normalTexture.index,
                          mat.pbrMetallicRoughness.metallicRoughnessTexture.index})
                if (int s = textureSource(t, who); s >= 0) images.insert(s);
        }
        return std::max<std::size_t>(images.size(), 1);
    }

    // The decoded image, or null (with a warning) when it is missing or unreadable.
    ImageData const* decoded(int image) {
        auto found = decoded_.find(image);
        if (found != decoded_.end()) return found->second ? &*found->second : nullptr;
        auto const& src = model_.images[std::size_t(image)];
        std::string const label = "image " + std::to_string(image) + (src.uri.empty() || src.uri.rfind("data:", 0) == 0
                                                                           ? std::string()
                                                                           : " ('" + printable(src.uri, 80) + "')");
        std::span<std::uint8_t const> bytes;
        if (src.bufferView >= 0) {
            bytes = reader_.bufferView(src.bufferView, "image " + std::to_string(image));
        } else if (auto it = stash_.encoded.find(image); it != stash_.encoded.end()) {
            bytes = it->second;
        }
        std::optional<ImageData> result;
        if (bytes.empty()) {
            scene_.warnings.push_back(label + " is missing; a placeholder texture is shown instead");
        } else {
            DecodedImage d = decodeImage(bytes, src.name.empty() ? label : src.name,
                                         src.mimeType.empty() ? std::string_view(src.uri) : std::string_view(src.mimeType),
                                         options_.maxImagePixels);
            if (d.overLimit) fail(label + ": " + d.error);
            if (!d.image) scene_.warnings.push_back(label + " cannot be used (" + d.error + "); a placeholder texture is shown instead");
            result = std::move(d.image);
        }
        ++imagesDecoded_;
        progress_.report(0.1f + 0.5f * float(imagesDecoded_) / float(imagesToDecode_), "decoding images");
        auto const& stored = decoded_.emplace(image, std::move(result)).first->second;
        return stored ? &*stored : nullptr;
    }

    // Index into scene_.images for a glTF image used as colour (sRGB) or as data (linear).
    int sceneImage(int image, bool srgb) {
        auto const key = std::make_pair(image, srgb);
        if (auto it = sceneImages_.find(key); it != sceneImages_.end()) return it->second;
        ImageData const* img = decoded(image);
        ImageData copy = img ? *img : placeholderImage("placeholder for image " + std::to_string(image));
        copy.srgb = srgb;
        scene_.images.push_back(std::move(copy));
        int const index = int(scene_.images.size() - 1);
        sceneImages_.emplace(key, index);
        return index;
    }

    int material(int index) {
        if (auto it = materials_.find(index); it != materials_.end()) return it->second;
        auto const& src = model_.materials[std::size_t(index)];
        std::string const who = "material " + std::to_string(index);
        Material mat;
        mat.name = src.name.empty() ? who : src.name;
        auto const& pbr = src.pbrMetallicRoughness;
        if (pbr.baseColorFactor.size() == 4)
            mat.baseColorFactor = glm::clamp(glm::vec4(float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]),
                                                       float(pbr.baseColorFactor[2]), float(pbr.baseColorFactor[3])),
                                             0.0f, 1.0f);
        else if (!pbr.baseColorFactor.empty())
            scene_.warnings.push_back(who + "'s baseColorFactor does not have 4 numbers; white is used");
        auto noteTexCoord = [&](int texCoord, char const* what) {
            if (texCoord != 0)
                scene_.warnings.push_back(who + "'s " + what + " uses TEXCOORD_" + std::to_string(texCoord) +
                                          "; only TEXCOORD_0 is loaded");
        };
        if (int s = textureSource(pbr.baseColorTexture.index, who); s >= 0) {
            mat.baseColorTexture = sceneImage(s, true);
            noteTexCoord(pbr.baseColorTexture.texCoord, "base colour texture");
        }
        if (int s = textureSource(src.normalTexture.index, who); s >= 0) {
            mat.normalTexture = sceneImage(s, false);
            mat.normalScale = std::isfinite(src.normalTexture.scale) ? float(src.normalTexture.scale) : 1.0f;
            noteTexCoord(src.normalTexture.texCoord, "normal texture");
        }

        // Specular intensity: docs/gltf.md, "glTF materials and lights".
        float weight = 1.0f;
        int specularImage = -1;
        Json const* specExt = nullptr;
        if (Json const* mats = member(doc_, "materials"); mats && std::size_t(index) < mats->size())
            if (Json const* ext = member((*mats)[std::size_t(index)], "extensions"))
                specExt = member(*ext, "KHR_materials_specular");
        if (specExt) {
            requireKind(*specExt, Kind::Object, who + "'s KHR_materials_specular");
            if (Json const* f = member(*specExt, "specularFactor")) {
                requireKind(*f, Kind::Number, who + "'s specularFactor");
                weight = f->get<float>();
            }
            if (Json const* f = member(*specExt, "specularColorFactor")) {
                requireKind(*f, Kind::NumberArray, who + "'s specularColorFactor");
                float strongest = 0.0f;
                for (auto const& c : *f) strongest = std::max(strongest, c.get<float>());
                if (!f->empty()) weight *= strongest;
            }
            if (Json const* t = member(*specExt, "specularTexture")) {
                requireKind(*t, Kind::Object, who + "'s specularTexture");
                if (Json const* i = member(*t, "index")) {
                    requireKind(*i, Kind::Index, who + "'s specularTexture.index");
                    specularImage = textureSource(int(std::min<std::uint64_t>(i->get<std::uint64_t>(), INT_MAX)), who);
                }
            }
        }
        float const metallic = float(pbr.metallicFactor), roughness = float(pbr.roughnessFactor);
        int const mrImage = textureSource(pbr.metallicRoughnessTexture.index, who);
        ImageData const* mr = mrImage >= 0 ? decoded(mrImage) : nullptr;
        ImageData const* sp = specularImage >= 0 ? decoded(specularImage) : nullptr;
        if (mr || sp) {
            // Bake once per distinct input: many materials share one texture set.
            std::string const key = std::to_string(mr ? mrImage : -1) + "/" + std::to_string(sp ? specularImage : -1) + "/" +
                                    std::to_string(metallic) + "/" + std::to_string(roughness) + "/" + std::to_string(weight);
            auto it = bakes_.find(key);
            if (it == bakes_.end()) {
                scene_.images.push_back(
                    bakeSpecularImage(mr, sp, metallic, roughness, weight, mat.name + " specular (baked)"));
                it = bakes_.emplace(key, int(scene_.images.size() - 1)).first;
            }
            mat.specularTexture = it->second;
            mat.specularFactor = 1.0f;
        } else {
            mat.specularFactor = specularFromMetallicRoughness(metallic, roughness, weight);
        }

        if (src.alphaMode == "MASK") mat.alphaMode = AlphaMode::Mask;
        else if (src.alphaMode == "BLEND") mat.alphaMode = AlphaMode::Blend;
        else if (src.alphaMode != "OPAQUE" && !src.alphaMode.empty())
            scene_.warnings.push_back(who + " has an unknown alphaMode '" + printable(src.alphaMode, 20) + "'; drawn opaque");
        mat.alphaCutoff = std::isfinite(src.alphaCutoff) ? float(src.alphaCutoff) : 0.5f;
        mat.doubleSided = src.doubleSided;

        scene_.materials.push_back(std::move(mat));
        int const ours = int(scene_.materials.size() - 1);
        materials_.emplace(index, ours);
        return ours;
    }

    // --- meshes -------------------------------------------------------------------------

    std::vector<int> buildMesh(int meshIndex) {
        auto const& mesh = model_.meshes[std::size_t(meshIndex)];
        std::vector<int> parts;
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            auto const& prim = mesh.primitives[p];
            std::string const who = "mesh " + std::to_string(meshIndex) + " primitive " + num(p);
            if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) {
                static constexpr char const* kModes[] = {"points", "lines", "line loops", "line strips",
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
                if (!std::isfinite(float(pos[i])))
                    fail(who + " has a NaN or infinite position at vertex " + num(i / 3));
            out.vertices.resize(n);
            for (std::size_t i = 0; i < n; ++i)
                out.vertices[i].position = glm::vec3(float(pos[3 * i]), float(pos[3 * i + 1]), float(pos[3 * i + 2]));

            auto sameCount = [&](std::vector<double> const& v, int comps, char const* what) {
                if (v.size() / std::size_t(comps) != n)
                    fail(who + " has " + num(v.size() / std::size_t(comps)) + " " + what + " values for " + num(n) + " positions");
            };
            bool haveNormals = false;
            if (int a = attr("NORMAL"); a >= 0) {
                std::vector<double> const v = reader_.read(a, who + " NORMAL", 3);
                sameCount(v, 3, "NORMAL");
                haveNormals = true;
                for (std::size_t i = 0; i < n && haveNormals; ++i) {
                    glm::vec3 const nn = glm::vec3(float(v[3 * i]), float(v[3 * i + 1]), float(v[3 * i + 2]));
                    float const len = glm::length(nn);
                    if (!(len > 0.0f) || !std::isfinite(len)) haveNormals = false;
                    else out.vertices[i].normal = nn / len;
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
                    if (!(len > 0.0f) || !std::isfinite(len) || !std::isfinite(float(v[4 * i + 3]))) haveTangents = false;
                    else out.vertices[i].tangent = glm::vec4(t / len, v[4 * i + 3] < 0.0 ? -1.0f : 1.0f);
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
            bool const normalMapped =
                prim.material >= 0 && scene_.materials[std::size_t(out.material)].normalTexture >= 0;
            if (normalMapped && !haveTangents) generateTangents(out);
            scene_.meshes.push_back(std::move(out));
            parts.push_back(int(scene_.meshes.size() - 1));
        }
        return parts;
    }

    // --- lights -------------------------------------------------------------------------

    void addLights(std::vector<std::pair<int, glm::mat4>> const& placed) {
        Json const* ext = member(doc_, "extensions");
        Json const* punctual = ext ? member(*ext, "KHR_lights_punctual") : nullptr;
        Json const* lights = punctual ? member(*punctual, "lights") : nullptr;
        if (lights) requireKind(*lights, Kind::Array, "KHR_lights_punctual.lights");
        Json const* nodes = member(doc_, "nodes");
        for (auto const& [node, world] : placed) {
            Json const* nodeExt = nodes ? member((*nodes)[std::size_t(node)], "extensions") : nullptr;
            Json const* ref = nodeExt ? member(*nodeExt, "KHR_lights_punctual") : nullptr;
            if (!ref) continue;
            std::string const who = "node " + std::to_string(node);
            requireKind(*ref, Kind::Object, who + "'s KHR_lights_punctual");
            Json const* li = member(*ref, "light");
            if (!li) continue;
            requireKind(*li, Kind::Index, who + "'s KHR_lights_punctual.light");
            std::uint64_t const l = li->get<std::uint64_t>();
            if (!lights || l >= lights->size())
                fail(who + " refers to light " + std::to_string(l) + ", but the file has " +
                     num(lights ? lights->size() : 0));
            Json const& light = (*lights)[l];
            std::string const lw = "light " + std::to_string(l);
            requireKind(light, Kind::Object, lw);
            std::string type = "point";
            if (Json const* t = member(light, "type")) requireKind(*t, Kind::String, lw + ".type"), type = t->get<std::string>();
            glm::vec3 color(1.0f);
            if (Json const* c = member(light, "color")) {
                requireKind(*c, Kind::NumberArray, lw + ".color");
                if (c->size() != 3) fail(lw + ".color has " + num(c->size()) + " numbers; expected 3");
                color = glm::vec3((*c)[0].get<float>(), (*c)[1].get<float>(), (*c)[2].get<float>());
            }
            float intensity = 1.0f, range = 0.0f;
            if (Json const* i = member(light, "intensity")) requireKind(*i, Kind::Number, lw + ".intensity"), intensity = i->get<float>();
            if (Json const* r = member(light, "range")) requireKind(*r, Kind::Number, lw + ".range"), range = r->get<float>();
            std::string name = "light " + std::to_string(l);
            if (Json const* nm = member(light, "name"); nm && nm->is_string()) name = nm->get<std::string>();
            if (type == "directional") {
                scene_.warnings.push_back(lw + " is directional; only point lights are loaded, so it is skipped");
                continue;
            }
            if (type == "spot")
                scene_.warnings.push_back(lw + " is a spot light; it is loaded as a point light without its cone");
            else if (type != "point") {
                scene_.warnings.push_back(lw + " has an unknown type '" + printable(type, 20) + "'; skipped");
                continue;
            }
            std::string why;
            auto pl = pointLightFromGltf(glm::vec3(world[3]), color, intensity, range, name, &why);
            if (!pl) {
                scene_.warnings.push_back(lw + " is skipped because " + why);
                continue;
            }
            if (lightRadius(*pl).kind == RadiusKind::Zero)
                scene_.warnings.push_back(lw + " is too dim to reach the light threshold; it lights nothing");
            scene_.lights.push_back(std::move(*pl));
        }
    }

    tinygltf::Model const& model_;
    Json const& doc_;
    ImageStash& stash_;
    GltfLoadOptions const& options_;
    Progress& progress_;
    ModelReader reader_;
    SceneData scene_;
    std::map<int, std::optional<ImageData>> decoded_;
    std::map<std::pair<int, bool>, int> sceneImages_;
    std::map<int, int> materials_;
    std::map<std::string, int> bakes_;
    std::size_t imagesToDecode_ = 1, imagesDecoded_ = 0;
    std::size_t uniqueTriangles_ = 0;
};

}  // namespace

SceneData buildScene(tinygltf::Model const& model, Json const& doc, ImageStash& stash, GltfLoadOptions const& options,
                     Progress& progress) {
    return SceneBuilder(model, doc, stash, options, progress).build();
}

}  // namespace gbl::gltf
