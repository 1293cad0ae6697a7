// msaa (docs/msaa.md): when a frame can have its multisampled G-buffer, and the run functions of
// its passes: the complex pixels' detection, their per-sample lighting and the resolve.
#include "renderer_impl.h"

#include "core/msaa.h"
#include "gl/shader_bindings.h"
#include "passes/lighting_quad.h"

#include <string>
#include <vector>

namespace gbl {

std::optional<std::string> RendererImpl::msaaRefusal(PipelineSettings const& s, bool makeTargets) {
    if (s.msaa == Msaa::Off) return std::nullopt;
    if (auto why = msaaFrameRefusal(s, bool(imported))) return why;
    int const n = msaaSamples(s.msaa);
    if (std::string const why = caps.msaaUnavailableReason(n); !why.empty()) return why + ", so msaa was off";
    if (!makeTargets || targets.msaa.samples == n) return std::nullopt;
    if (auto err = createMsaaTargets(n, targets))
        return "the " + std::to_string(n) + "-sample G-buffer could not be made (" + *err + "), so msaa was off";
    return std::nullopt;
}

gl::Program const& RendererImpl::msaaProgram(std::string const& what) {
    std::string define = "GBL_MSAA_SAMPLES " + std::to_string(targets.msaa.samples);
    if (!what.empty()) define += "\n#define GBL_MSAA_" + what;
    return shaders.variant(ProgramId::LightingQuad, define);
}

// The complex pixels: the quad program's detection variant draws where the samples differ, which
// sets the mask and the lit target's stencil mark (StencilUse::MarkComplex); the others discard.
void RendererImpl::runMsaaEdges(FrameRecord& frame, PassRun const& r) {
    glBindFramebuffer(GL_FRAMEBUFFER, r.fbo->id());
    applyGroup(r.decl.states, 0);  // mask and stencil cleared by the executor (PassDecl::clears)
    gl::Program const& p = msaaProgram("EDGES");
    p.use();
    bindDeferredInputs(p, {gbufferTextures(targets.msaa.gbuffer), lights, frame.shading});
    p.set("uMsaaRelativeDistance", kMsaaThresholds.relativeDistance);
    p.set("uMsaaNormalCos", kMsaaThresholds.normalCos);
    p.set("uMsaaAlbedo", kMsaaThresholds.albedo);
    if (!complexQuery) complexQuery = gl::Query::create(GL_SAMPLES_PASSED, "msaa complex pixels");
    complexQuery.begin();  // the drawn fragments are the complex pixels (the mask is single-sampled)
    triangle.draw();
    complexQuery.end();
    frame.complexCounted = true;
}

// msaa edges: the marked pixels, every sample lit and averaged, beside the simple ones.
void RendererImpl::runLightingComplex(FrameRecord& frame, PassRun const& r) {
    DeferredInputs const deferred = deferredInputs(frame.f, r.io);
    lightingQuadPass({{gbufferTextures(targets.msaa.gbuffer), deferred.lights, deferred.shading},
                      msaaProgram(""),
                      triangle,
                      {*r.fbo, r.io.texture(Resource::Lighting)},
                      r.decl.states});
}

// Each colour attachment averaged into the layout's own (one read buffer to one draw buffer at a
// time), then depth and stencil (one sample): what the views, the depth copy and the counts read.
void RendererImpl::runMsaaResolve(FrameRecord&, PassRun const& r) {
    GBuffer const& from = targets.msaa.gbuffer;
    int const w = targets.width, h = targets.height;
    apply(kWriteAll);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, from.fbo.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, r.fbo->id());
    std::vector<GLenum> all;
    for (std::size_t i = 0; i < r.decl.color.size(); ++i) all.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
    for (std::size_t i = 0; i < all.size(); ++i) {
        std::vector<GLenum> one(all.size(), GL_NONE);
        one[i] = all[i];
        glReadBuffer(all[i]);
        glDrawBuffers(GLsizei(one.size()), one.data());
        glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    glDrawBuffers(GLsizei(all.size()), all.data());  // the G-buffer's framebuffer as it was made
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace gbl
