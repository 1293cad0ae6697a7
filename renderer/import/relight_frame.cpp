// The imported G-buffer as the renderer's import pass takes it.
#include "import/relight_frame.h"

#include <algorithm>
#include <cmath>

namespace gbl {

namespace {

// Window depth ([0, 1], as gl_FragCoord.z) of a clip-space point.
float windowDepth(glm::vec4 clip) {
    return clip.z / clip.w * 0.5f + 0.5f;
}

}  // namespace

RelightFrame relightFrame(ImportedGBuffer const& g) {
    RelightFrame out;
    std::string const label = g.manifest.label.empty() ? std::string("manifest") : g.manifest.label;
    if (!g.camera) {
        out.error = label + ": camera is missing, and re-lighting needs the camera the G-buffer was drawn with";
        return out;
    }
    if (g.albedo.empty()) {
        out.error = label + ": albedo is missing, and re-lighting needs the surface colour";
        return out;
    }
    if (g.position.empty()) {
        out.error = label + ": position is missing, and neither a position file nor depth gives it";
        return out;
    }
    CameraMatrices const& c = *g.camera;
    ImportedFrame f;
    f.width = g.width;
    f.height = g.height;
    f.view = c.view;
    f.projection = c.projection;
    f.eye = c.position;
    glm::mat4 const& p = c.projection;
    // A perspective projection's planes, when the manifest gave none.
    f.nearPlane = c.nearPlane.value_or(p[3][2] / (p[2][2] - 1.0f));
    f.farPlane = c.farPlane.value_or(p[3][2] / (p[2][2] + 1.0f));
    glm::mat4 const viewProj = p * c.view;
    std::size_t const n = g.pixelCount();
    f.positionDepth.resize(n);
    f.normal.resize(n);
    f.albedoSpec.resize(n);
    // Emission 0 and occlusion 1 where the manifest gives neither: today's frame exactly.
    if (!g.emissive.empty() || !g.occlusion.empty()) f.emissiveAo.resize(n);
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x) {
            std::size_t const from = std::size_t(y) * std::size_t(g.width) + std::size_t(x);
            std::size_t const to = std::size_t(g.height - 1 - y) * std::size_t(g.width) + std::size_t(x);  // bottom-up
            glm::vec3 const pos = g.position[from];
            float depth = 1.0f;  // background
            if (!g.background[from] && !g.nonFinite[from]) {
                // The stored depth when there is one (exact for the export's own depth.exr), else the
                // position's through the camera.
                depth = !g.viewDistance.empty() ? windowDepth(p * glm::vec4(0.0f, 0.0f, -g.viewDistance[from], 1.0f))
                                                : windowDepth(viewProj * glm::vec4(pos, 1.0f));
                depth = std::isfinite(depth) ? std::clamp(depth, 0.0f, 1.0f) : 1.0f;
            }
            f.positionDepth[to] = glm::vec4(pos, depth);
            f.normal[to] = glm::vec4(g.normal[from], 0.0f);
            f.albedoSpec[to] = glm::vec4(g.albedo[from], g.specular.empty() ? 0.0f : g.specular[from]);
            if (!f.emissiveAo.empty())
                f.emissiveAo[to] = glm::vec4(g.emissive.empty() ? glm::vec3(0.0f) : g.emissive[from],
                                             g.occlusion.empty() ? 1.0f : g.occlusion[from]);
        }
    out.frame = std::move(f);
    return out;
}

Camera cameraOfFrame(ImportedFrame const& f) {
    Camera c;
    c.position = f.eye;
    glm::vec3 const forward = -glm::normalize(glm::vec3(f.view[0][2], f.view[1][2], f.view[2][2]));
    c.pitchDegrees = glm::degrees(std::asin(glm::clamp(forward.y, -1.0f, 1.0f)));
    c.yawDegrees = glm::degrees(std::atan2(forward.z, forward.x));
    c.fovYDegrees = glm::degrees(2.0f * std::atan(1.0f / f.projection[1][1]));
    c.nearPlane = f.nearPlane;
    c.farPlane = f.farPlane;
    c.fixedView = f.view;
    c.fixedProjection = f.projection;
    return c;
}

}  // namespace gbl
