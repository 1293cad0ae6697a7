// libFuzzer target: the glTF loader must refuse or load any bytes without crashing, and what it
// loads must satisfy the invariants the renderer relies on.
#include "gltf/loader.h"

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace {

// Small limits keep each input fast; the limit checks themselves are part of what is fuzzed.
gbl::GltfLoadOptions fuzzOptions() {
    gbl::GltfLoadOptions o;
    o.maxFileBytes = std::size_t(1) << 20;
    o.maxTriangles = 1 << 16;
    o.maxVertices = 1 << 16;
    o.maxImagePixels = 1 << 16;
    o.maxNodes = 1024;
    return o;
}

void check(bool ok) {
    if (!ok) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(std::uint8_t const* data, std::size_t size) {
    static gbl::GltfLoadOptions const options = fuzzOptions();
    // A folder that does not exist: external URIs resolve to nothing instead of real files.
    gbl::GltfLoadResult const r =
        gbl::loadGltfFromMemory({data, size}, "/nonexistent-gbuffer-lab-fuzz/input.gltf", options);
    check(r.scene.has_value() == r.error.empty());
    if (!r.scene) return 0;
    gbl::SceneData const& s = *r.scene;
    for (auto const& m : s.meshes) {
        check(m.indices.size() % 3 == 0);
        for (auto i : m.indices) check(i < m.vertices.size());
        for (auto const& v : m.vertices)
            check(std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z));
        check(m.material >= -1 && m.material < int(s.materials.size()));
    }
    for (auto const& inst : s.instances) check(inst.mesh >= 0 && std::size_t(inst.mesh) < s.meshes.size());
    for (auto const& img : s.images)
        check(img.width > 0 && img.height > 0 && img.channels >= 1 && img.channels <= 4 &&
              img.pixels.size() == std::size_t(img.width) * std::size_t(img.height) * std::size_t(img.channels));
    for (auto const& mat : s.materials)
        for (int t : {mat.baseColorTexture, mat.normalTexture, mat.specularTexture})
            check(t >= -1 && t < int(s.images.size()));
    check(!s.lights.empty() && s.camera.has_value());
    return 0;
}
