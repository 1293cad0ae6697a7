// The declared passes of deferred lighting (prepass mode).
#include "core/frame_passes.h"
#include "core/frame_passes_parts.h"

namespace gbl {

namespace {

using R = Resource;

// The light pass with `prepass_lights: volumes`: the directional lights full screen (they have no
// volume), then every light's volume with the cull mode, each adding its diffuse and specular light.
// The volumes test against a copy of the thin pass's depth-stencil (the pass samples the depth itself,
// and attaching what a pass samples is a feedback loop): volumeDepthPass(LitDepth) makes it first.
PassDecl volumeLightPass(PipelineSettings const& s) {
    PassDecl l =
        detail::volumePass(PassId::Lighting, layoutDesc(s.layout), s.cull, {R::DiffuseLight, R::SpecularLight});
    l.samples = {R::PrepassNormal, R::LitDepth, R::Lights, R::VolumeInstances};
    l.depthStencil = R::VolumeDepth;  // splitVolumeFbo
    l.clears = l.color;
    l.states.insert(l.states.begin(), detail::fullScreen("directional lights"));
    return l;
}

}  // namespace

std::vector<PassDecl> prepassPasses(PipelineSettings const& s) {
    // Both of the scene's draw groups (drawScene): back faces culled, then the double-sided materials.
    auto const scene = [](std::string_view single, std::string_view both, DepthTest test, bool depthWrite) {
        return std::vector<DrawState>{{single, test, depthWrite, Blend::Off, FaceCull::Back},
                                      {both, test, depthWrite, Blend::Off, FaceCull::Off}};
    };
    PassDecl g;  // the thin G-buffer: its normal target with the lit target's depth
    g.id = PassId::ThinGBuffer;
    g.samples = {R::Materials};
    g.color = {R::PrepassNormal};
    g.depthStencil = R::LitDepth;
    g.depthRead = g.depthWrite = true;
    g.states = scene("opaque surfaces, normal and exponent", "double-sided opaque surfaces, normal and exponent",
                     DepthTest::Less, true);
    g.clears = {R::PrepassNormal};
    PassDecl l;  // splitFbo: no depth-stencil attached, the depth is sampled
    l.id = PassId::Lighting;
    l.samples = {R::PrepassNormal, R::LitDepth, R::Lights};
    l.color = l.clears = {R::DiffuseLight, R::SpecularLight};
    l.states = {{"every light", DepthTest::Off, false, Blend::Off, FaceCull::Off}};
    PassDecl c;  // the lit target, tested against the thin pass's depth (equal where it drew), not written
    c.id = PassId::PrepassShading;
    c.samples = {R::Materials, R::DiffuseLight, R::SpecularLight};
    c.color = {R::Lighting};
    c.depthStencil = R::LitDepth;
    c.depthRead = true;
    c.states = scene("opaque surfaces, light buffer", "double-sided opaque surfaces, light buffer",
                     DepthTest::LessEqual, false);
    c.clears = {R::Lighting};
    if (!drawsLightVolumes(s)) return {std::move(g), std::move(l), std::move(c)};
    return {std::move(g), detail::volumeDepthPass(R::LitDepth), volumeLightPass(s), std::move(c)};
}

}  // namespace gbl
