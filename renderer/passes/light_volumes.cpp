// Light volumes: instance lists, the cull modes and the volumes lighting pass.
#include "passes/light_volumes.h"

#include "core/light_math.h"
#include "core/light_volume_mesh.h"
#include "gl/shader_bindings.h"

#include <glm/gtc/constants.hpp>

#include <cstdint>
#include <vector>

namespace gbl {

void prepareVolumeInstances(LightVolumeGpu& volumes, VolumeInstancesConfig const& c) {
    std::vector<std::int32_t> outside, inside;
    float const nearCorner = nearPlaneCornerDistance(glm::radians(c.camera.fovYDegrees), c.aspect, c.camera.nearPlane);
    for (std::size_t i = 0; i < c.lights.size(); ++i) {
        float const r = lightRadius(c.lights[i]).radius;
        if (r <= 0.0f) continue;  // too dim or invalid: no volume at all
        bool const in =
            volumeMayContainCamera(c.camera.position, c.lights[i].position, r * volumes.enclosingScale, nearCorner);
        (in ? inside : outside).push_back(std::int32_t(i));
    }
    volumes.outsideCount = int(outside.size());
    volumes.insideCount = int(inside.size());
    outside.insert(outside.end(), inside.begin(), inside.end());
    if (outside.empty()) outside.push_back(0);  // a buffer texture needs storage
    std::size_t const bytes = outside.size() * sizeof(std::int32_t);
    if (!volumes.instances || volumes.instances.size() < bytes) {
        volumes.instances =
            gl::Buffer::create(GL_TEXTURE_BUFFER, bytes, outside.data(), GL_DYNAMIC_DRAW, "light volume.instances");
        volumes.instancesTbo = gl::Texture::createBuffer(GL_R32I, volumes.instances.id(), "light volume.instances.tbo");
    } else {
        volumes.instances.upload(bytes, outside.data());
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
void drawLightVolumes(LightVolumeDraw const& in, glm::mat4 const& viewProj, CullMode cull) {
    LightVolumeGpu const& volumes = in.volumes;
    int const total = volumes.outsideCount + volumes.insideCount;
    if (total == 0) return;
    gl::Program const& p = in.program;
    auto setCommon = [&](gl::Program const& prog) {
        prog.use();
        bindDeferredInputs(prog, in.deferred);
        bindTextureUnit(slot::BIND_VOLUME_INSTANCES, GL_TEXTURE_BUFFER, volumes.instancesTbo.id());
        prog.set("uViewProj", viewProj);
        prog.set("uEnclosingScale", volumes.enclosingScale);
    };
    auto draw = [&](gl::Program const& prog, int first, int count) {
        if (count <= 0) return;
        prog.set("uFirstInstance", first);
        glDrawElementsInstanced(GL_TRIANGLES, volumes.triangleIndexCount, GL_UNSIGNED_INT, nullptr, count);
    };
    auto frontFaces = [] {  // cull back faces: the front faces in front of the surface
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
    };
    auto backFaces = [] {  // cull front faces: the back faces behind the surface
        glEnable(GL_CULL_FACE);
        glCullFace(GL_FRONT);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GEQUAL);
        // No GL_DEPTH_CLAMP to keep back faces past the far plane: it also lifts near-plane
        // clipping, and llvmpipe then rasterises the parts of a volume behind the eye wrongly.
        // The cost: a light whose volume crosses the far plane misses surfaces right at it.
    };

    glDepthMask(GL_FALSE);
    glBindVertexArray(volumes.triangleVao.id());
    setCommon(p);
    switch (cull) {
        case CullMode::Back:
            frontFaces();
            draw(p, 0, total);
            break;
        case CullMode::Front:
            backFaces();
            draw(p, 0, total);
            break;
        case CullMode::None:
            glDisable(GL_CULL_FACE);
            glDisable(GL_DEPTH_TEST);
            draw(p, 0, total);
            break;
        case CullMode::Flip:
            frontFaces();
            draw(p, 0, volumes.outsideCount);
            backFaces();
            draw(p, volumes.outsideCount, volumes.insideCount);
            break;
        case CullMode::Stencil: {
            gl::Program const& mark = in.stencilMark;
            setCommon(mark);
            glEnable(GL_STENCIL_TEST);
            GLboolean blend = glIsEnabled(GL_BLEND);
            for (int i = 0; i < total; ++i) {
                // Mark: both faces, depth-tested, no colour; only depth failures count.
                mark.use();
                glDisable(GL_BLEND);
                glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
                glDisable(GL_CULL_FACE);
                glEnable(GL_DEPTH_TEST);
                glDepthFunc(GL_LESS);
                glStencilFunc(GL_ALWAYS, 0, 0xFF);
                glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
                glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
                draw(mark, i, 1);
                // Shade: both faces, no depth test, so every pixel of the footprint is visited; only
                // a mark of exactly 1 (behind the front face, in front of the back face) passes,
                // and every visit resets the mark to 0 for the next light, pass or fail (which is
                // why light_volume.frag never discards).
                p.use();
                if (blend) glEnable(GL_BLEND);
                glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
                glDisable(GL_DEPTH_TEST);
                glStencilFunc(GL_EQUAL, 1, 0xFF);
                glStencilOp(GL_ZERO, GL_ZERO, GL_ZERO);
                draw(p, i, 1);
            }
            glDisable(GL_STENCIL_TEST);
            glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
            glStencilFunc(GL_ALWAYS, 0, 0xFF);
            break;
        }
    }
    glBindVertexArray(0);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
}

// --- lighting: volumes ---------------------------------------------------------------------------
LightingOutput lightingVolumesPass(LightingVolumesInput const& in, LightingVolumesConfig const& config) {
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.fbo.id());
    // Ambient (and zero on the background) with the full-screen program and no lights, so the
    // ambient term is the very same expression as in the quad pass.
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    in.ambient.use();
    bindDeferredInputs(in.ambient, in.deferred);
    in.ambient.set("uLightCount", 0);
    in.triangle.draw();

    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    drawLightVolumes({in.deferred, in.volumes, in.shade, in.stencilMark}, config.viewProj, config.cull);
    glDisable(GL_BLEND);
    return {in.target.hdr};
}

}  // namespace gbl
