// The msaa passes' declarations (docs/msaa.md): the detection, the resolve, the complex pixels' quad
// pass, and the volumes lit from the samples.
#include "core/frame_passes_parts.h"
#include "core/msaa.h"

namespace gbl::detail {

using R = Resource;

namespace {

Resource msaaResource(GBufferSlot slot) {
    switch (slot) {
        case GBufferSlot::Position:
            return R::MsaaPosition;
        case GBufferSlot::Normal:
            return R::MsaaNormal;
        case GBufferSlot::AlbedoSpec:
            return R::MsaaAlbedoSpec;
        case GBufferSlot::Emissive:
            return R::MsaaEmissive;
        case GBufferSlot::Depth:
            break;
    }
    return R::MsaaDepth;
}

}  // namespace

// The multisampled twins of the layout's colour attachments, in draw-buffer order.
std::vector<Resource> msaaColor(GBufferLayoutDesc const& d) {
    std::vector<Resource> out;
    for (GBufferAttachmentDesc const& a : d.colorAttachments()) out.push_back(msaaResource(a.slot));
    return out;
}

// What the lighting reads of the multisampled G-buffer: gbufferSamples' twins.
std::vector<Resource> msaaGBufferSamples(GBufferLayoutDesc const& d) {
    std::vector<Resource> out{lightingSamplesDepth(d) ? R::MsaaDepth : R::MsaaPosition, R::MsaaNormal,
                              R::MsaaAlbedoSpec};
    if (storesEmissiveAo(d)) out.push_back(R::MsaaEmissive);
    return out;
}

// Whether the frame lights a multisampled G-buffer (the renderer turns msaa off where it cannot, and
// says why: core/msaa.h).
bool msaaFrame(PipelineSettings const& s, bool imported) {
    return s.msaa != Msaa::Off && !msaaFrameRefusal(s, imported);
}
// Whether its lighting reads the samples themselves (not the resolved G-buffer).
bool lightsSamples(PipelineSettings const& s) {
    return s.msaaLighting != MsaaLighting::ResolveFirst;
}

// The complex pixels found: the mask written and the lit target's stencil marked where samples differ.
PassDecl msaaEdgesPass(GBufferLayoutDesc const& d) {
    PassDecl p = declare(PassId::MsaaEdges);
    p.samples = msaaGBufferSamples(d);
    if (storesEmissiveAo(d)) p.samples.pop_back();  // compares position, normal and albedo only
    p.color = {R::ComplexMask};
    p.depthStencil = R::LitDepth;
    p.stencilWrite = true;
    p.clears = {R::ComplexMask, R::LitDepth};
    p.states = {
        state("mark complex pixels", DepthTest::Off, false, Blend::Off, FaceCull::Off, StencilUse::MarkComplex)};
    return p;
}

// The multisampled G-buffer resolved (averaged; depth and stencil: one sample) into the layout's
// targets, which the views, the depth copy and the counts read as in any frame.
PassDecl msaaResolvePass(GBufferLayoutDesc const& d) {
    PassDecl p = declare(PassId::MsaaResolve, PassKind::Blit);
    p.samples = msaaColor(d);
    p.samples.push_back(R::MsaaDepth);
    for (GBufferAttachmentDesc const& a : d.colorAttachments()) p.color.push_back(slotResource(a.slot));
    p.depthStencil = R::GBufferDepth;
    p.depthWrite = p.stencilWrite = true;
    return p;
}

namespace {

// The complex pixels' volume draws (msaa volumes): their samples lie on different surfaces, so no one
// depth can test them. The cull mode's faces with no depth test, the shader's radius cut-off keeping
// each sample to the light's sphere, which the mesh encloses; stencil's mark needs a depth test, so it
// draws the back faces alone, as front does (what the mark would let through: a surface inside).
std::vector<DrawState> complexVolumeStates(CullMode cull) {
    std::vector<DrawState> out = volumeStates(msaaComplexCull(cull));
    for (DrawState& v : out) {
        v = onPixels(v, MsaaPixels::Complex);
        v.depthTest = DepthTest::Off;
    }
    return out;
}

}  // namespace

// msaa volumes (per-sample and edges; docs/msaa.md): the volumes added into the single-sample lit image
// over its depth-stencil, which holds the complex bit (msaa_edges) and a resolved depth (volume_depth).
// The ambient term first: each pixel's samples averaged, or under edges the simple pixels lit once.
// Then the simple pixels, one surface under every sample, depth-tested with the cull mode's states:
// per-sample lights every sample in the shader and averages, edges lights the centre once. Then the
// complex pixels, every sample lit and averaged, with no depth test (complexVolumeStates): the same
// draws in both strategies, so they agree there bit for bit.
PassDecl msaaVolumesPass(PipelineSettings const& s, GBufferLayoutDesc const& d) {
    bool const edges = s.msaaLighting == MsaaLighting::Edges;
    PassDecl p = declare(PassId::Lighting);
    p.samples = plus(msaaGBufferSamples(d), {R::Lights, R::VolumeInstances});
    p.color = {R::Lighting};
    p.depthStencil = R::LitDepth;
    p.clears = {R::Lighting};
    p.depthRead = s.cull != CullMode::None;
    p.stencilRead = true;
    p.stencilWrite = s.cull == CullMode::Stencil;
    if (edges)
        p.states = {onPixels(fullScreen("ambient, simple pixels"), MsaaPixels::Simple),
                    onPixels(fullScreen("ambient, complex pixels"), MsaaPixels::Complex)};
    else
        p.states = {fullScreen("ambient, every sample")};
    for (DrawState const& v : volumeStates(s.cull)) p.states.push_back(onPixels(v, MsaaPixels::Simple));
    for (DrawState const& v : complexVolumeStates(s.cull)) p.states.push_back(v);
    return p;
}

// The volumes' depth: the multisampled depth resolved (one sample) into the lit target's depth, whose
// stencil keeps the complex bit msaa_edges set. A simple pixel's samples lie on one surface, and the
// volumes' faces meet a surface only outside the light's sphere, so one sample's depth tests it as
// every sample's would.
PassDecl msaaVolumeDepthPass() {
    PassDecl v = declare(PassId::VolumeDepth, PassKind::Blit);
    v.samples = {R::MsaaDepth};
    v.color = {R::Lighting};  // litFbo's; the blit writes depth only
    v.depthStencil = R::LitDepth;
    v.depthWrite = true;
    return v;
}

// msaa edges: the complex pixels, each sample lit, into the lit image beside the simple ones.
PassDecl lightingComplexPass(GBufferLayoutDesc const& d) {
    PassDecl p = declare(PassId::MsaaComplex);
    p.samples = plus(msaaGBufferSamples(d), {R::Lights});
    p.color = {R::Lighting};
    p.depthStencil = R::LitDepth;
    p.stencilRead = true;
    p.states = {onPixels(fullScreen("complex pixels"), MsaaPixels::Complex)};
    return p;
}

}  // namespace gbl::detail
