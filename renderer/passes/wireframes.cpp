// Light-volume wireframes pass: an overlay on the display image.
#include "passes/wireframes.h"
#include "gl/draw_count.h"

#include "core/light_math.h"
#include "core/light_volume_mesh.h"
#include "gl/shader_bindings.h"
#include "passes/light_volumes.h"

#include <algorithm>

namespace gbl {

// The same partition as prepareVolumeInstances (light_volumes.cpp): a light's slot is its rank
// among the lights of its group, after every outside light when it is inside.
std::optional<int> volumeInstanceSlot(std::span<PointLight const> lights, int light, Camera const& camera, float aspect,
                                      float enclosingScale, float coneRadialScale, float volumeScale) {
    if (light < 0 || std::size_t(light) >= lights.size()) return std::nullopt;
    VolumeGrouping const g{camera.position,
                           nearPlaneCornerDistance(glm::radians(camera.fovYDegrees), aspect, camera.nearPlane),
                           enclosingScale, coneRadialScale, volumeScale};
    int before[4] = {0, 0, 0, 0}, size[4] = {0, 0, 0, 0};  // per group: lights before `light`, all lights
    VolumeGroup own = VolumeGroup::None;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        VolumeGroup const group = volumeGroup(lights[i], g);
        if (group == VolumeGroup::None) continue;
        ++size[int(group) - 1];
        if (int(i) < light) ++before[int(group) - 1];
        if (int(i) == light) own = group;
    }
    if (own == VolumeGroup::None) return std::nullopt;
    int slot = before[int(own) - 1];
    for (int k = 0; k < int(own) - 1; ++k) slot += size[k];  // the groups stored before its own
    return slot;
}

void wireframesPass(WireframesInput const& in, WireframesConfig const& config) {
    LightVolumeGpu const& v = in.volumes;
    int const prepared = v.totalCount();
    int const first = std::clamp(config.firstInstance, 0, prepared);
    int const total = config.count < 0 ? prepared - first : std::min(config.count, prepared - first);
    int const arrows = config.count < 0 ? int(in.lights.directional.size()) : 0;
    if (total <= 0 && arrows == 0) return;
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.id());
    applyGroup(config.states, 0);
    gl::Program const& p = in.program;
    p.use();
    bindLights(p, in.lights);
    bindTextureUnit(slot::BIND_VOLUME_INSTANCES, v.instancesTbo.target(), v.instancesTbo.id());
    p.set("uViewProj", config.viewProj);
    p.set("uEnclosingScale", v.enclosingScale);
    p.set("uConeRadialScale", v.coneRadialScale);
    p.set("uVolumeScale", v.volumeScale);
    p.set("uWireIntensity", config.intensity);
    setTonemapUniforms(p, config.tonemap);
    // The requested range split at the sphere/cone boundary: spheres first, then cones (the spot's
    // cone is its direction and angle drawn in the viewport).
    int const sphereEnd = v.sphereCount(), end = first + total;
    auto drawRange = [&](GLuint vao, GLsizei indexCount, int from, int to, bool cone) {
        if (to <= from) return;
        p.set("uFirstInstance", from);
        p.set("uCone", cone ? 1 : 0);
        glBindVertexArray(vao);
        glDrawElementsInstanced(GL_LINES, indexCount, GL_UNSIGNED_INT, nullptr, to - from);
        gl::countDraw(0);  // lines
    };
    drawRange(v.lineVao.id(), v.lineIndexCount, first, std::min(end, sphereEnd), false);
    drawRange(v.coneLineVao.id(), v.coneLineIndexCount, std::max(first, sphereEnd), end, true);
    if (arrows > 0) {  // instance k: the k-th directional light (uDirectionalLights, set by bindLights)
        p.set("uCone", 0);
        p.set("uArrow", 1);
        p.set("uArrowLength", config.arrowLength);
        glBindVertexArray(v.arrowVao.id());
        glDrawElementsInstanced(GL_LINES, v.arrowLineIndexCount, GL_UNSIGNED_INT, nullptr, arrows);
        gl::countDraw(0);  // lines
        p.set("uArrow", 0);
    }
    glBindVertexArray(0);
}

}  // namespace gbl
