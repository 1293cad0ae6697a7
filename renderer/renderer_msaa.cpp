// msaa (docs/msaa.md): when a frame can have its multisampled G-buffer, and the run functions of
// its passes: the complex pixels' detection, their per-sample lighting and the resolve.
#include "renderer_impl.h"

#include "core/msaa.h"
#include "gl/shader_bindings.h"
#include "passes/light_volumes.h"
#include "passes/lighting_quad.h"

#include <algorithm>
#include <span>
#include <string>
#include <vector>

namespace gbl {

std::optional<std::string> RendererImpl::msaaRefusal(PipelineSettings const& s, bool makeTargets) {
    if (s.msaa == Msaa::Off) return std::nullopt;
    if (auto why = msaaFrameRefusal(s, bool(imported))) return why;
    int const n = msaaSamples(s.msaa);
    if (std::string const why = caps.msaaUnavailableReason(n); !why.empty()) return why + ", so msaa was off";
    double const bytes = msaaTargetBytes(layoutDesc(s.layout), n, targets.width, targets.height);
    bool const reported = caps.freeVideoMemoryKiB > 0;
    double const budget = reported ? double(caps.freeVideoMemoryKiB) * 1024.0 / 2.0 : kMsaaFixedBudgetBytes;
    std::string const source = reported ? "half the free video memory " + caps.freeVideoMemorySource + " reported"
                                        : "fixed, as this driver does not report its free memory";
    if (auto why = msaaBudgetRefusal(s.msaa, bytes, budget, source, targets.width, targets.height)) return why;
    if (!makeTargets || targets.msaa.samples == n) return std::nullopt;
    if (auto err = createMsaaTargets(n, targets))
        return "the " + std::to_string(n) + "-sample G-buffer could not be made (" + *err + "), so msaa was off";
    return std::nullopt;
}

namespace {

// Each sample's place in its pixel, for the layouts that rebuild position from depth (gbuffer_read.glsl).
void setSamplePositions(gl::Program const& p, MsaaTargets const& m) {
    p.use();
    glUniform2fv(p.uniform("uSamplePositions[0]"), GLsizei(m.samplePositions.size()),
                 reinterpret_cast<GLfloat const*>(m.samplePositions.data()));
}

// The detection variant's thresholds (core/msaa.h).
void setMsaaThresholds(gl::Program const& p) {
    p.set("uMsaaRelativeDistance", kMsaaThresholds.relativeDistance);
    p.set("uMsaaNormalCos", kMsaaThresholds.normalCos);
    p.set("uMsaaAlbedo", kMsaaThresholds.albedo);
}

}  // namespace

gl::Program const& RendererImpl::msaaProgram(std::string const& what, ProgramId id) {
    std::string define = "GBL_MSAA_SAMPLES " + std::to_string(targets.msaa.samples);
    if (!what.empty()) define += "\n#define GBL_MSAA_" + what;
    gl::Program const& p = shaders.variant(id, define);
    setSamplePositions(p, targets.msaa);
    setMsaaThresholds(p);  // the detection's and the decode pass's counts' (the others have none: ignored)
    return p;
}

// The complex pixels: the quad program's detection variant draws where the samples differ, which
// sets the mask and the lit target's stencil mark (StencilUse::MarkComplex); the others discard.
void RendererImpl::runMsaaEdges(FrameRecord& frame, PassRun const& r) {
    glBindFramebuffer(GL_FRAMEBUFFER, r.fbo->id());
    applyGroup(r.decl.states, 0);  // mask and stencil cleared by the executor (PassDecl::clears)
    gl::Program const& p = msaaProgram("EDGES");
    p.use();
    bindDeferredInputs(p, {gbufferTextures(targets.msaa.gbuffer), lights, frame.shading});
    setMsaaThresholds(p);
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

// msaa volumes (core/frame_passes_msaa.cpp, msaaVolumesPass, declares the groups in this order), into
// the single-sample lit image: the ambient term (edges: the simple pixels lit once, the complex ones
// averaged; per-sample: every pixel averaged), then the volumes over the simple pixels with the cull
// mode's states (edges: lit once at the centre; per-sample: every sample lit and averaged), then over
// the complex pixels, every sample lit and averaged, with msaaComplexCull's faces and no depth test.
void RendererImpl::runMsaaVolumes(FrameRecord& frame, PassRun const& r) {
    FrameContext const& f = frame.f;
    bool const edges = f.settings.msaaLighting == MsaaLighting::Edges;
    DeferredInputs const deferred{gbufferTextures(targets.msaa.gbuffer), lights, frame.shading};
    glBindFramebuffer(GL_FRAMEBUFFER, r.fbo->id());
    std::size_t group = 0;
    auto const ambient = [&](gl::Program const& p) {
        applyGroup(r.decl.states, group++);
        p.use();
        bindDeferredInputs(p, deferred);
        p.set("uLightCount", 0);  // the ambient term (and directional lights) alone, as lightingVolumesPass
        triangle.draw();
    };
    if (edges) ambient(msaaProgram("SAMPLE0"));  // the simple pixels: lit once, at the centre
    ambient(msaaProgram(""));                    // the samples averaged
    std::string const samples = "GBL_MSAA_SAMPLES " + std::to_string(targets.msaa.samples);
    auto const volumeProgram = [&](bool once) -> gl::Program const& {
        gl::Program const& p =
            shaders.variant(ProgramId::LightVolume, once ? samples + "\n#define GBL_MSAA_SAMPLE0" : samples);
        setSamplePositions(p, targets.msaa);
        return p;
    };
    // The volume groups: the simple pixels' first, up to the first group kept to complex pixels.
    std::span<DrawState const> const all(r.decl.states);
    auto const complex = std::find_if(all.begin() + std::ptrdiff_t(group), all.end(),
                                      [](DrawState const& d) { return d.pixels == MsaaPixels::Complex; });
    std::size_t const simpleGroups = std::size_t(complex - all.begin()) - group;
    gl::Program const& stencilMark = shaders.get(ProgramId::LightVolumeStencil);
    drawLightVolumes({deferred, volumes, volumeProgram(edges), stencilMark}, f.viewProj, f.settings.cull,
                     all.subspan(group, simpleGroups));
    drawLightVolumes({deferred, volumes, volumeProgram(false), stencilMark}, f.viewProj,
                     msaaComplexCull(f.settings.cull), all.subspan(group + simpleGroups));
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace gbl
