// Light volumes: instance lists, the cull modes and the volumes lighting pass.
#include "passes/light_volumes.h"
#include "gl/draw_count.h"

#include "core/light_math.h"
#include "core/light_volume_cone.h"
#include "core/light_volume_mesh.h"
#include "gl/shader_bindings.h"

#include <glm/gtc/constants.hpp>

#include <cstdint>
#include <vector>

namespace gbl {

VolumeGroup volumeGroup(PointLight const& light, VolumeGrouping const& g) {
    VolumeShape const shape = volumeShape(light);
    if (shape == VolumeShape::None) return VolumeGroup::None;  // directional: the ambient pass's global loop
    float const r = lightRadius(light).radius;
    if (r <= 0.0f) return VolumeGroup::None;  // too dim or invalid: no volume at all
    if (shape == VolumeShape::Cone)
        return coneMayContainCamera(g.eye, coneVolume(light, r, g.coneRadialScale, g.volumeScale), g.nearCorner)
                   ? VolumeGroup::ConeInside
                   : VolumeGroup::ConeOutside;
    return volumeMayContainCamera(g.eye, light.position, r * g.sphereScale, g.nearCorner) ? VolumeGroup::SphereInside
                                                                                          : VolumeGroup::SphereOutside;
}

void prepareVolumeInstances(LightVolumeGpu& volumes, VolumeInstancesConfig const& c) {
    std::vector<std::int32_t> groups[4];  // in VolumeGroup order, None left out
    VolumeGrouping const g{c.camera.position,
                           nearPlaneCornerDistance(glm::radians(c.camera.fovYDegrees), c.aspect, c.camera.nearPlane),
                           volumes.enclosingScale, volumes.coneRadialScale, volumes.volumeScale};
    for (std::size_t i = 0; i < c.lights.size(); ++i) {
        VolumeGroup const group = volumeGroup(c.lights[i], g);
        if (group != VolumeGroup::None) groups[int(group) - 1].push_back(std::int32_t(i));
    }
    volumes.outsideCount = int(groups[0].size());
    volumes.insideCount = int(groups[1].size());
    volumes.coneOutsideCount = int(groups[2].size());
    volumes.coneInsideCount = int(groups[3].size());
    std::vector<std::int32_t> all;
    for (auto const& group : groups) all.insert(all.end(), group.begin(), group.end());
    if (all.empty()) all.push_back(0);  // a buffer texture needs storage
    if (!gl::kBufferTextures) {
        // WebGL2: rows of an R32I texture (shaders/light_volume.vert's instanceLight).
        int const rows = int((all.size() + gl::kLightTexelsPerRow - 1) / gl::kLightTexelsPerRow);
        all.resize(std::size_t(rows) * gl::kLightTexelsPerRow, 0);
        if (!volumes.instancesTbo || volumes.instancesTbo.height() < rows) {
            volumes.instancesTbo =
                gl::Texture::create2D(GL_R32I, gl::kLightTexelsPerRow, rows, "light volume.instances");
            volumes.instancesTbo.setFilter(GL_NEAREST, GL_NEAREST);
        }
        glBindTexture(GL_TEXTURE_2D, volumes.instancesTbo.id());
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, gl::kLightTexelsPerRow, rows, GL_RED_INTEGER, GL_INT, all.data());
        glBindTexture(GL_TEXTURE_2D, 0);
        return;
    }
    std::size_t const bytes = all.size() * sizeof(std::int32_t);
    if (!volumes.instances || volumes.instances.size() < bytes) {
        volumes.instances =
            gl::Buffer::create(GL_TEXTURE_BUFFER, bytes, all.data(), GL_DYNAMIC_DRAW, "light volume.instances");
        volumes.instancesTbo = gl::Texture::createBuffer(GL_R32I, volumes.instances.id(), "light volume.instances.tbo");
    } else {
        volumes.instances.upload(bytes, all.data());
    }
}

// --- drawing the volumes with one cull mode ----------------------------------------------------
// Depth tests run against the G-buffer depth (the bound framebuffer's depth-stencil):
//   back:    front faces where they are in front of the surface. Fails when the camera is inside
//            a volume: its front faces are behind the near plane and the light vanishes.
//   front:   back faces where they are behind the surface; survives the camera inside.
//   none:    both faces, no depth test (the tutorials' first attempt): every pixel under a volume
//            is shaded twice, once per face. Kept as the visible bug.
//   flip:    per light, front-face culling when the camera may be inside its volume, back-face
//            culling otherwise.
//   stencil: per light, a stencil pass marks the pixels whose surface lies inside the volume
//            (back face behind the surface +1, front face behind the surface -1), then the
//            volume shades only pixels marked 1 and resets every mark.
void drawLightVolumes(LightVolumeDraw const& in, glm::mat4 const& viewProj, CullMode cull,
                      std::span<DrawState const> groups) {
    LightVolumeGpu const& volumes = in.volumes;
    if (volumes.totalCount() == 0) return;
    gl::Program const& p = in.program;
    auto setCommon = [&](gl::Program const& prog) {
        prog.use();
        bindDeferredInputs(prog, in.deferred);
        bindTextureUnit(slot::BIND_VOLUME_INSTANCES, volumes.instancesTbo.target(), volumes.instancesTbo.id());
        prog.set("uViewProj", viewProj);
        prog.set("uEnclosingScale", volumes.enclosingScale);
        prog.set("uConeRadialScale", volumes.coneRadialScale);
        prog.set("uVolumeScale", volumes.volumeScale);
    };
    // The mesh being drawn: the sphere lights' range of instances, then the cone lights'.
    struct Mesh {
        GLuint vao;
        GLsizei indexCount;
        int base, outsideCount, insideCount;
        bool cone;
    };
    Mesh const meshes[] = {
        {volumes.triangleVao.id(), volumes.triangleIndexCount, 0, volumes.outsideCount, volumes.insideCount, false},
        {volumes.coneTriangleVao.id(), volumes.coneTriangleIndexCount, volumes.sphereCount(), volumes.coneOutsideCount,
         volumes.coneInsideCount, true}};
    Mesh const* mesh = &meshes[0];
    auto draw = [&](gl::Program const& prog, int first, int count) {
        if (count <= 0) return;
        prog.set("uFirstInstance", mesh->base + first);
        prog.set("uCone", mesh->cone ? 1 : 0);
        glDrawElementsInstanced(GL_TRIANGLES, mesh->indexCount, GL_UNSIGNED_INT, nullptr, count);
        gl::countDraw(std::uint64_t(mesh->indexCount / 3) * std::uint64_t(count));
    };
    // The draw groups of each cull mode, in the order core/frame_passes.cpp (volumeStates) declares
    // them: back, front and none one group; flip the front faces of the lights outside, then the
    // back faces of those whose volume may hold the camera; stencil a mark and a shade per light.
    // Back faces are kept past the far plane by no GL_DEPTH_CLAMP: it also lifts near-plane clipping,
    // and llvmpipe then rasterises the parts of a volume behind the eye wrongly. The cost: a light
    // whose volume crosses the far plane misses surfaces right at it.
    setCommon(p);
    if (cull == CullMode::Stencil) setCommon(in.stencilMark);
    for (Mesh const& m : meshes) {
        mesh = &m;
        int const total = m.outsideCount + m.insideCount;
        if (total == 0) continue;
        glBindVertexArray(m.vao);
        p.use();
        switch (cull) {
            case CullMode::Back:
            case CullMode::Front:
            case CullMode::None:
                applyGroup(groups, 0);
                draw(p, 0, total);
                break;
            case CullMode::Flip:
                applyGroup(groups, 0);
                draw(p, 0, m.outsideCount);
                applyGroup(groups, 1);
                draw(p, m.outsideCount, m.insideCount);
                break;
            case CullMode::Stencil:
                for (int i = 0; i < total; ++i) {
                    // Mark: both faces, depth-tested, no colour; only depth failures count.
                    in.stencilMark.use();
                    applyGroup(groups, 0);
                    draw(in.stencilMark, i, 1);
                    // Shade: both faces, no depth test, so every pixel of the footprint is visited; only
                    // a mark of exactly 1 (behind the front face, in front of the back face) passes,
                    // and every visit resets the mark to 0 for the next light, pass or fail (which is
                    // why light_volume.frag never discards).
                    p.use();
                    applyGroup(groups, 1);
                    draw(p, i, 1);
                }
                break;
        }
    }
    glBindVertexArray(0);
}

// --- lighting: volumes ---------------------------------------------------------------------------
LightingOutput lightingVolumesPass(LightingVolumesInput const& in, LightingVolumesConfig const& config) {
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.fbo.id());
    // Ambient (and zero on the background) with the full-screen program and no lights, so the
    // ambient term is the very same expression as in the quad pass.
    applyGroup(config.states, 0);
    in.ambient.use();
    bindDeferredInputs(in.ambient, in.deferred);
    in.ambient.set("uLightCount", 0);
    in.triangle.draw();

    drawLightVolumes({in.deferred, in.volumes, in.shade, in.stencilMark}, config.viewProj, config.cull,
                     config.states.subspan(1));
    return {in.target.hdr};
}

}  // namespace gbl
