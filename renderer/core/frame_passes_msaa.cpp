// The msaa passes' declarations (docs/msaa.md): the detection, the resolves, and the volumes lit
// sample by sample into a multisampled image.
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

// msaa volumes (per-sample and edges; docs/msaa.md): the volumes added into the multisampled lit
// image, tested against the multisampled depth-stencil, one sample at a time (the sample mask; the
// shader lights that sample). edges first sets the stencil's complex bit (the detection again, with
// no colour), lights the simple pixels once at their centre (every sample written) and then the
// complex ones sample by sample; per-sample lights every pixel sample by sample. The ambient term is
// each pixel's samples averaged (lit once at simple pixels), written to every sample.
PassDecl msaaVolumesPass(PipelineSettings const& s, GBufferLayoutDesc const& d) {
    bool const edges = s.msaaLighting == MsaaLighting::Edges;
    PassDecl p = declare(PassId::Lighting);
    p.samples = plus(msaaGBufferSamples(d), {R::Lights, R::VolumeInstances});
    p.color = {R::MsaaLighting};
    p.depthStencil = lightingSamplesDepth(d) ? R::MsaaVolumeDepth : R::MsaaDepth;
    p.clears = {R::MsaaLighting};
    p.depthRead = s.cull != CullMode::None;
    p.stencilRead = p.stencilWrite = s.cull == CullMode::Stencil || edges;
    std::vector<DrawState> const volumes = volumeStates(s.cull);
    auto const addVolumes = [&](MsaaPixels pixels, int sample) {
        for (DrawState const& v : volumes) p.states.push_back(onPixels(v, pixels, sample));
    };
    if (edges) {
        p.states = {state("mark complex pixels", DepthTest::Off, false, Blend::Off, FaceCull::Off,
                          StencilUse::MarkComplex, false),
                    onPixels(fullScreen("ambient, simple pixels"), MsaaPixels::Simple),
                    onPixels(fullScreen("ambient, complex pixels"), MsaaPixels::Complex)};
        addVolumes(MsaaPixels::Simple, -1);
    } else {
        p.states = {fullScreen("ambient, every sample")};
    }
    for (int k = 0; k < msaaSamples(s.msaa); ++k) addVolumes(edges ? MsaaPixels::Complex : MsaaPixels::All, k);
    return p;
}

// The volumes' copy of the multisampled depth-stencil (layouts whose lighting samples the depth).
PassDecl msaaVolumeDepthPass() {
    PassDecl v = declare(PassId::VolumeDepth, PassKind::Blit);
    v.samples = {R::MsaaDepth};
    v.color = {R::MsaaLighting};  // the blit writes depth and stencil only
    v.depthStencil = R::MsaaVolumeDepth;
    v.depthWrite = v.stencilWrite = true;
    return v;
}

// The multisampled lit image averaged into the lit image (the G-buffer is resolved after it).
PassDecl msaaResolveLightingPass() {
    PassDecl p = declare(PassId::MsaaResolveLighting, PassKind::Blit);
    p.samples = {R::MsaaLighting};
    p.color = {R::Lighting};
    return p;
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
