// The glTF loader's scene builder: the build sequence and the node hierarchy.
#include "gltf/scene_builder.h"

#include "gltf/mapping.h"
#include "gltf/scene_builder_parts.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

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

}  // namespace

SceneData SceneBuilder::build() {
    std::vector<std::pair<int, glm::mat4>> const placed = placeNodes();

    // Materials first: their images dominate the time, and primitives need to know about normal maps.
    std::set<int> usedMaterials;
    for (auto const& [node, world] : placed) {
        int const meshIndex = model_.nodes[std::size_t(node)].mesh;
        if (meshIndex < 0) continue;
        if (std::size_t(meshIndex) >= model_.meshes.size())
            fail("node " + std::to_string(node) + " refers to mesh " + std::to_string(meshIndex) +
                 ", but the file has " + num(model_.meshes.size()));
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
    addCameras(placed, bounds);
    return std::move(scene_);
}

// Validates the node graph (a forest: in-range children, one parent each, no cycles) and
// returns the nodes of the chosen scene with their world matrices.
std::vector<std::pair<int, glm::mat4>> SceneBuilder::placeNodes() {
    std::size_t const n = model_.nodes.size();
    std::vector<int> parent(n, -1);
    for (std::size_t i = 0; i < n; ++i) {
        for (int c : model_.nodes[i].children) {
            if (c < 0 || std::size_t(c) >= n)
                fail("node " + num(i) + " lists child " + std::to_string(c) + ", but the file has " + num(n) +
                     " nodes");
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

SceneData buildScene(tinygltf::Model const& model, Json const& doc, ImageStash& stash, GltfLoadOptions const& options,
                     Progress& progress) {
    return SceneBuilder(model, doc, stash, options, progress).build();
}

}  // namespace gbl::gltf
