// libFuzzer target: the G-buffer manifest reader (renderer/import) must refuse or accept any bytes
// without crashing, refuse with one message that starts with the manifest's name, and what it
// accepts must hold the values the decoding and the re-light rely on (finite lights and camera,
// channel indices 0..3, raw sizes in range).
#include "import/gbuffer_manifest.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace {

void check(bool ok) {
    if (!ok) __builtin_trap();
}

bool finite(glm::mat4 const& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

void checkImage(gbl::ImageRef const& ref) {
    check(!ref.path.empty());
    check(!ref.channels.empty() && ref.channels.size() <= 4);
    for (int c : ref.channels) check(c >= 0 && c <= 3);
    if (ref.raw) check(ref.raw->width > 0 && ref.raw->height > 0 && ref.raw->channels >= 1 && ref.raw->channels <= 4);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(std::uint8_t const* data, std::size_t size) {
    std::string_view const text(reinterpret_cast<char const*>(data), size);
    // A folder that does not exist: the reader resolves names against it and reads no file.
    gbl::ManifestLoad const r = gbl::parseManifest(text, "fuzz.json", "/nonexistent-gbuffer-lab-fuzz");
    check(r.manifest.has_value() == r.error.empty());
    if (!r.manifest) {
        check(r.error.rfind("fuzz.json", 0) == 0);
        return 0;
    }
    gbl::GBufferManifest const& m = *r.manifest;
    check(m.position.has_value() != m.positionFromDepth);
    if (m.position) {
        checkImage(m.position->image);
        if (m.position->coverageChannel) check(*m.position->coverageChannel >= 0 && *m.position->coverageChannel <= 3);
    }
    checkImage(m.normal.image);
    if (m.albedo) checkImage(m.albedo->image);
    if (m.specular) checkImage(*m.specular);
    if (m.emissive) {
        checkImage(m.emissive->image);
        check(std::isfinite(m.emissive->scale) && m.emissive->scale >= 0.0f);
    }
    if (m.occlusion) checkImage(*m.occlusion);
    if (m.lit) checkImage(*m.lit);
    if (m.depth) {
        checkImage(m.depth->image);
        check(std::isfinite(m.depth->nearPlane) && std::isfinite(m.depth->farPlane));
    }
    check(std::isfinite(m.shininess) && m.shininess > 0.0f);
    if (m.camera) {
        check(finite(m.camera->view) && finite(m.camera->projection));
        // The projection a fov-given camera gets once the image size is known.
        gbl::CameraMatrices const sized = gbl::cameraForSize(*m.camera, 64, 36);
        check(finite(sized.view) && finite(sized.projection));
    }
    for (gbl::PointLight const& l : m.lights) {
        check(std::isfinite(l.position.x) && std::isfinite(l.position.y) && std::isfinite(l.position.z));
        check(std::isfinite(l.color.r) && std::isfinite(l.color.g) && std::isfinite(l.color.b));
        check(std::isfinite(l.kc) && std::isfinite(l.kl) && std::isfinite(l.kq) && std::isfinite(l.intensity));
    }
    return 0;
}
