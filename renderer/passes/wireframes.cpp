// Light-volume wireframes pass.
#include "passes/wireframes.h"

#include "core/light_math.h"
#include "core/light_volume_mesh.h"
#include "gl/shader_bindings.h"

#include <algorithm>

namespace gbl {

// The same partition as prepareVolumeInstances (light_volumes.cpp): a light's slot is its rank
// among the lights of its group, after every outside light when it is inside.
std::optional<int> volumeInstanceSlot(std::span<PointLight const> lights, int light, Camera const& camera, float aspect,
                                      float enclosingScale) {
    if (light < 0 || std::size_t(light) >= lights.size()) return std::nullopt;
    float const nearCorner = nearPlaneCornerDistance(glm::radians(camera.fovYDegrees), aspect, camera.nearPlane);
    int outsideBefore = 0, insideBefore = 0, outside = 0;
    bool lightInside = false, hasVolume = false;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        float const r = lightRadius(lights[i]).radius;
        if (r <= 0.0f) continue;
        bool const in = volumeMayContainCamera(camera.position, lights[i].position, r * enclosingScale, nearCorner);
        outside += in ? 0 : 1;
        if (int(i) < light) (in ? insideBefore : outsideBefore) += 1;
        if (int(i) == light) {
            hasVolume = true;
            lightInside = in;
        }
    }
    if (!hasVolume) return std::nullopt;
    return lightInside ? outside + insideBefore : outsideBefore;
}

void wireframesPass(WireframesInput const& in, WireframesConfig const& config) {
    int const prepared = in.volumes.outsideCount + in.volumes.insideCount;
    int const first = std::clamp(config.firstInstance, 0, prepared);
    int const total = config.count < 0 ? prepared - first : std::min(config.count, prepared - first);
    if (total <= 0) return;
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.fbo.id());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    gl::Program const& p = in.program;
    p.use();
    bindLights(p, in.lights);
    bindTextureUnit(slot::BIND_VOLUME_INSTANCES, GL_TEXTURE_BUFFER, in.volumes.instancesTbo.id());
    p.set("uViewProj", config.viewProj);
    p.set("uEnclosingScale", in.volumes.enclosingScale);
    p.set("uFirstInstance", first);
    p.set("uWireIntensity", config.intensity);
    glBindVertexArray(in.volumes.lineVao.id());
    glDrawElementsInstanced(GL_LINES, in.volumes.lineIndexCount, GL_UNSIGNED_INT, nullptr, total);
    glBindVertexArray(0);
    glEnable(GL_CULL_FACE);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
}

}  // namespace gbl
