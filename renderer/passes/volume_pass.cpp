// Light volumes: one enclosing sphere per light, drawn instanced and added by blending, with
// the five cull modes of the volumes pass (back, front, none, flip, stencil).
#include "renderer_impl.h"

#include "core/light_math.h"
#include "core/light_volume_mesh.h"

#include <glm/gtc/constants.hpp>

#include <stdexcept>

namespace gbl {

namespace {

// Texture unit of the instance list; 0..2 hold the G-buffer and 3 the lights.
constexpr int kInstanceUnit = 4;

std::vector<ProgramDesc> volumePrograms(bool compute) {
    std::vector<ProgramDesc> p = {
        {"light_volume", {{GL_VERTEX_SHADER, "light_volume.vert"}, {GL_FRAGMENT_SHADER, "light_volume.frag"}}, {}},
        {"light_volume_coverage",
         {{GL_VERTEX_SHADER, "light_volume.vert"}, {GL_FRAGMENT_SHADER, "light_volume.frag"}},
         {"COVERAGE"}},
        {"light_volume_stencil",
         {{GL_VERTEX_SHADER, "light_volume.vert"}, {GL_FRAGMENT_SHADER, "light_volume_stencil.frag"}},
         {}},
        {"light_volume_wire", {{GL_VERTEX_SHADER, "light_volume.vert"}, {GL_FRAGMENT_SHADER, "light_volume_wire.frag"}}, {}},
        {"coverage_all_lights",
         {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "coverage_all_lights.frag"}},
         {}},
    };
    if (compute) p.push_back({"lighting_tiled", {{GL_COMPUTE_SHADER, "lighting_tiled.comp"}}, {}});
    return p;
}

}  // namespace

void RendererImpl::initLightVolumes() {
    if (volumes) return;
    for (auto& desc : volumePrograms(caps.computeShaders)) {
        std::string log;
        if (!shaders.add(desc, &log))
            throw std::runtime_error("Renderer: built-in shader program '" + desc.name + "' failed to build:\n" + log);
    }
    SphereMesh const mesh = makeLightVolumeSphere();
    volumes.enclosingScale = enclosingScale(mesh);
    volumes.vertices = gl::Buffer::create(GL_ARRAY_BUFFER, mesh.positions.size() * sizeof(glm::vec3), mesh.positions.data(),
                                          GL_STATIC_DRAW, "light volume.vertices");
    volumes.triangles = gl::Buffer::create(GL_ELEMENT_ARRAY_BUFFER, mesh.triangles.size() * sizeof(std::uint32_t),
                                           mesh.triangles.data(), GL_STATIC_DRAW, "light volume.triangles");
    volumes.lines = gl::Buffer::create(GL_ELEMENT_ARRAY_BUFFER, mesh.lines.size() * sizeof(std::uint32_t), mesh.lines.data(),
                                       GL_STATIC_DRAW, "light volume.lines");
    volumes.triangleIndexCount = GLsizei(mesh.triangles.size());
    volumes.lineIndexCount = GLsizei(mesh.lines.size());
    auto makeVao = [&](gl::VertexArray& vao, gl::Buffer const& indices, char const* label) {
        vao = gl::VertexArray::create(label);
        glBindVertexArray(vao.id());
        glBindBuffer(GL_ARRAY_BUFFER, volumes.vertices.id());
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices.id());
        glBindVertexArray(0);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
    };
    makeVao(volumes.triangleVao, volumes.triangles, "light volume");
    makeVao(volumes.lineVao, volumes.lines, "light volume.wire");
}

void RendererImpl::prepareVolumeInstances(FrameContext const& f) {
    initLightVolumes();
    // Lights whose volume may hold the camera go last, so `flip` draws two contiguous ranges.
    std::vector<std::int32_t> outside, inside;
    float const nearCorner = nearPlaneCornerDistance(glm::radians(f.camera.fovYDegrees), f.aspect, f.camera.nearPlane);
    for (std::size_t i = 0; i < f.lights.size(); ++i) {
        float const r = lightRadius(f.lights[i]).radius;
        if (r <= 0.0f) continue;  // too dim or invalid: no volume at all
        bool const in = volumeMayContainCamera(f.camera.position, f.lights[i].position, r * volumes.enclosingScale, nearCorner);
        (in ? inside : outside).push_back(std::int32_t(i));
    }
    volumes.outsideCount = int(outside.size());
    volumes.insideCount = int(inside.size());
    outside.insert(outside.end(), inside.begin(), inside.end());
    if (outside.empty()) outside.push_back(0);  // a buffer texture needs storage
    std::size_t const bytes = outside.size() * sizeof(std::int32_t);
    if (!volumes.instances || volumes.instances.size() < bytes) {
        volumes.instances = gl::Buffer::create(GL_TEXTURE_BUFFER, bytes, outside.data(), GL_DYNAMIC_DRAW, "light volume.instances");
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
void RendererImpl::drawLightVolumes(FrameContext const& f, gl::Program const& p, CullMode cull) {
    int const total = volumes.outsideCount + volumes.insideCount;
    if (total == 0) return;
    auto setCommon = [&](gl::Program const& prog) {
        prog.use();
        bindLightingInputs(prog, f);
        glActiveTexture(GLenum(GL_TEXTURE0 + kInstanceUnit));
        glBindTexture(GL_TEXTURE_BUFFER, volumes.instancesTbo.id());
        glActiveTexture(GL_TEXTURE0);
        prog.set("uInstances", kInstanceUnit);
        prog.set("uViewProj", f.viewProj);
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
        gl::Program const& mark = shaders.get("light_volume_stencil");
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
// Cost: one full-screen ambient pass plus the pixels each light's volume covers, not
// pixels x lights.
void RendererImpl::lightingVolumesPass(FrameContext const& f) {
    prepareVolumeInstances(f);
    glBindFramebuffer(GL_FRAMEBUFFER, targets.volumeFbo.id());
    // Ambient (and zero on the background) with the full-screen program and no lights, so the
    // ambient term is the very same expression as in the quad pass.
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    gl::Program const& ambient = shaders.get("lighting_quad");
    ambient.use();
    bindLightingInputs(ambient, f);
    ambient.set("uLightCount", 0);
    glBindVertexArray(emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);

    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    drawLightVolumes(f, shaders.get("light_volume"), f.settings.cull);
    glDisable(GL_BLEND);
}

}  // namespace gbl
