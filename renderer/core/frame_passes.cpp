// The declared passes of a frame and the feedback-loop check over them.
#include "core/frame_passes.h"
#include "core/frame_passes_parts.h"

#include "core/gbuffer_layout.h"
#include "core/msaa.h"

#include <algorithm>

namespace gbl {

namespace detail {

using R = Resource;

PassDecl declare(PassId id, PassKind kind) {
    PassDecl p;
    p.id = id;
    p.kind = kind;
    return p;
}

DrawState state(std::string_view what, DepthTest depthTest, bool depthWrite, Blend blend, FaceCull cull,
                StencilUse stencil, bool colorWrite) {
    return {what, depthTest, depthWrite, blend, cull, stencil, colorWrite};
}

Resource slotResource(GBufferSlot slot) {
    switch (slot) {
        case GBufferSlot::Position:
            return R::GBufferPosition;
        case GBufferSlot::Normal:
            return R::GBufferNormal;
        case GBufferSlot::AlbedoSpec:
            return R::GBufferAlbedoSpec;
        case GBufferSlot::Emissive:
            return R::GBufferEmissive;
        case GBufferSlot::Depth:
            break;
    }
    return R::GBufferDepth;
}

// What shaders/gbuffer_read.glsl samples in `layout`: position, or the depth it is rebuilt from.
std::vector<Resource> gbufferSamples(GBufferLayoutDesc const& d) {
    std::vector<Resource> out{lightingSamplesDepth(d) ? R::GBufferDepth : R::GBufferPosition, R::GBufferNormal,
                              R::GBufferAlbedoSpec};
    if (storesEmissiveAo(d)) out.push_back(R::GBufferEmissive);
    return out;
}

std::vector<Resource> plus(std::vector<Resource> a, std::initializer_list<Resource> b) {
    for (Resource r : b)
        if (std::find(a.begin(), a.end(), r) == a.end()) a.push_back(r);
    return a;
}

// The draw groups of the scene (gpu/gpu_scene.h, drawScene, which applies them): the materials with
// back faces culled, then glTF's double-sided materials, drawn with no culling.
std::vector<DrawState> sceneStates(std::string_view single, std::string_view both, bool depthWrite, Blend blend) {
    return {state(single, DepthTest::Less, depthWrite, blend, FaceCull::Back),
            state(both, DepthTest::Less, depthWrite, blend, FaceCull::Off)};
}

DrawState fullScreen(std::string_view what) {
    return state(what, DepthTest::Off, false, Blend::Off, FaceCull::Off);
}

// `drawn` kept to the msaa simple or complex pixels (core/frame_passes.h).
DrawState onPixels(DrawState drawn, MsaaPixels pixels) {
    drawn.pixels = pixels;
    return drawn;
}

// passes/light_volumes.cpp, drawLightVolumes: the draws of one cull mode, each added (blend ONE, ONE).
std::vector<DrawState> volumeStates(CullMode cull) {
    DrawState const front = state("volumes: front faces", DepthTest::Less, false, Blend::Add, FaceCull::Back);
    DrawState const back = state("volumes: back faces", DepthTest::GreaterEqual, false, Blend::Add, FaceCull::Front);
    switch (cull) {
        case CullMode::Back:
            return {front};
        case CullMode::Front:
            return {back};
        case CullMode::None:
            return {state("volumes: both faces", DepthTest::Off, false, Blend::Add, FaceCull::Off)};
        case CullMode::Flip:
            return {front, back};
        case CullMode::Stencil:
            return {state("stencil mark", DepthTest::Less, false, Blend::Off, FaceCull::Off, StencilUse::Mark, false),
                    state("stencil shade", DepthTest::Off, false, Blend::Add, FaceCull::Off, StencilUse::ShadeMarked)};
    }
    return {};
}

// The volumes drawn into `color` against the volume depth-stencil (lighting and coverage).
PassDecl volumePass(PassId id, GBufferLayoutDesc const& d, CullMode cull, std::vector<Resource> color) {
    PassDecl p = declare(id);
    p.samples = plus(gbufferSamples(d), {R::Lights, R::VolumeInstances});
    p.color = std::move(color);
    p.depthStencil = lightingSamplesDepth(d) ? R::VolumeDepth : R::GBufferDepth;
    p.depthRead = cull != CullMode::None;
    p.stencilRead = p.stencilWrite = cull == CullMode::Stencil;
    p.states = volumeStates(cull);
    return p;
}

PassDecl computePass(PassId id, std::vector<Resource> samples, std::vector<Resource> writes) {
    PassDecl p = declare(id, PassKind::Compute);
    p.samples = std::move(samples);
    p.writes = std::move(writes);
    return p;
}

// The lit target (litFbo: lighting + its own depth-stencil) drawn with one state.
PassDecl litPass(PassId id, std::vector<Resource> samples, DrawState drawn) {
    PassDecl p = declare(id);
    p.samples = std::move(samples);
    p.color = {R::Lighting};
    p.depthStencil = R::LitDepth;
    p.depthRead = drawn.depthTest != DepthTest::Off;
    p.depthWrite = drawn.depthWrite;
    p.states = {drawn};
    return p;
}

// A pass that draws the scene (gpu/gpu_scene.h, drawScene) into the lit target: its two draw groups.
PassDecl scenePass(PassId id, std::vector<Resource> samples, std::vector<DrawState> states) {
    PassDecl p = litPass(id, std::move(samples), states.front());
    p.states = std::move(states);
    return p;
}

// An overlay (core/frame_passes.h, viewShowsOverlays): drawn onto the display image after the view
// pass, depth-tested against `depth` (RenderTargets::overlayFbo or overlayGBufferDepthFbo).
PassDecl overlayPass(PassId id, std::vector<Resource> samples, Resource depth, DrawState drawn) {
    PassDecl p = declare(id);
    p.samples = std::move(samples);
    p.color = {R::Display};
    p.depthStencil = depth;
    p.depthRead = drawn.depthTest != DepthTest::Off;
    p.depthWrite = drawn.depthWrite;
    p.states = {drawn};
    return p;
}

// The volumes' copy of the G-buffer depth-stencil, where the lighting samples the G-buffer's depth
// (prepass's volumes: of the thin pass's depth, which its light pass samples).
PassDecl volumeDepthPass(Resource source) {
    PassDecl v = declare(PassId::VolumeDepth, PassKind::Blit);
    v.samples = {source};
    v.color = {R::Lighting};  // volumeFbo's; the blit writes depth and stencil only
    v.depthStencil = R::VolumeDepth;
    v.depthWrite = v.stencilWrite = true;
    return v;
}

}  // namespace detail

namespace {

using namespace detail;
using R = Resource;

PassDecl lightingPass(PipelineSettings const& s, bool split) {
    GBufferLayoutDesc const& d = layoutDesc(s.layout);
    std::vector<Resource> const lit = split ? std::vector{R::DiffuseLight, R::SpecularLight} : std::vector{R::Lighting};
    switch (s.mode) {
        case LightingMode::Volumes: {
            PassDecl p = volumePass(PassId::Lighting, d, s.cull, lit);
            p.states.insert(p.states.begin(), fullScreen("ambient"));
            return p;
        }
        case LightingMode::Tiled:
            return computePass(PassId::Lighting, plus(gbufferSamples(d), {R::Lights, R::TileBins}), lit);
        case LightingMode::Clustered:
            return computePass(PassId::Lighting, plus(gbufferSamples(d), {R::Lights, R::ClusterLists}), lit);
        case LightingMode::Quad:
        case LightingMode::Forward:
        case LightingMode::ForwardPlus:
        case LightingMode::Prepass:  // prepassPasses
            break;
    }
    PassDecl p = declare(PassId::Lighting);  // full screen into litFbo, or splitFbo (no depth-stencil)
    p.samples = plus(gbufferSamples(d), {R::Lights});
    if (msaaFrame(s, false) && lightsSamples(s)) p.samples = plus(msaaGBufferSamples(d), {R::Lights});
    p.color = lit;
    p.clears = lit;
    if (!split) p.depthStencil = R::LitDepth;
    p.states = {fullScreen("every light")};
    if (msaaFrame(s, false) && s.msaaLighting == MsaaLighting::Edges) {  // sample 0 of the simple pixels
        p.stencilRead = true;
        p.states = {onPixels(fullScreen("simple pixels"), MsaaPixels::Simple)};
    }
    return p;
}

PassDecl depthCopyPass(DepthCopy mode) {
    PassDecl p = declare(PassId::DepthCopy, mode == DepthCopy::Blit ? PassKind::Blit : PassKind::Raster);
    p.color = {R::Lighting};
    p.depthStencil = R::LitDepth;
    p.depthWrite = p.stencilWrite = true;  // cleared, then written
    p.clears = {R::LitDepth};
    if (mode != DepthCopy::Off) p.samples = {R::GBufferDepth};
    if (mode == DepthCopy::Shader)
        p.states = {
            {"depth from the shader", DepthTest::Always, true, Blend::Off, FaceCull::Off, StencilUse::Off, false}};
    return p;
}

PassDecl coverageCounts(PipelineSettings const& s);

PassDecl coveragePass(PipelineSettings const& s) {
    PassDecl p = coverageCounts(s);
    p.clears = {R::Coverage};
    return p;
}

// The view pass: the frame's data, tonemapped or shown raw, into `target` (the display or a view).
// A prepass frame's G-buffer views read its thin G-buffer (normal and exponent, the lit depth):
// the layout's attachments hold nothing of that frame (docs/deferred_lighting.md).
PassDecl displayPass(GBufferLayoutDesc const& d, Resource target, bool thin) {
    PassDecl v = declare(PassId::Display);
    if (thin)
        v.samples = {R::PrepassNormal, R::LitDepth};
    else
        for (GBufferAttachmentDesc const& a : d.attachments()) v.samples.push_back(slotResource(a.slot));  // raw views
    v.samples = plus(v.samples, {R::Lighting, R::Coverage, R::DiffuseLight, R::SpecularLight});
    v.color = {target};
    v.states = {fullScreen("view")};
    return v;
}

// Where the blended surfaces are, hatched over every view (the G-buffer views included, which they
// are absent from): drawn with no depth test, so a pane behind a wall is hatched too.
PassDecl glassOutlinePass(Resource target) {
    PassDecl p = declare(PassId::GlassOutline);
    p.samples = {R::Materials};
    p.color = {target};
    p.states = {state("blended surfaces, hatched", DepthTest::Off, false, Blend::Off, FaceCull::Back),
                state("double-sided blended surfaces, hatched", DepthTest::Off, false, Blend::Off, FaceCull::Off)};
    return p;
}

PassDecl coverageCounts(PipelineSettings const& s) {
    GBufferLayoutDesc const& d = layoutDesc(s.layout);
    std::vector<Resource> const gbuffer = plus(gbufferSamples(d), {R::GBufferDepth});  // and tile depth bounds
    if (s.mode == LightingMode::ForwardPlus)  // the frame's own lists, counted over its pre-pass depth
        return computePass(PassId::Coverage, {R::LitDepth, R::Lights, R::TileBins}, {R::Coverage});
    if (s.view == DebugView::TileLights || s.mode == LightingMode::Tiled)
        return computePass(PassId::Coverage, plus(gbuffer, {R::Lights}), {R::Coverage, R::TileBins});
    if (s.mode == LightingMode::Clustered)
        return computePass(PassId::Coverage, plus(gbuffer, {R::Lights}), {R::Coverage, R::TileBins, R::ClusterLists});
    if (s.mode == LightingMode::Volumes) return volumePass(PassId::Coverage, d, s.cull, {R::Coverage});
    PassDecl p = declare(PassId::Coverage);  // coverageFbo: the counts over the volume depth-stencil, unused here
    p.color = {R::Coverage};
    p.depthStencil = lightingSamplesDepth(d) ? R::VolumeDepth : R::GBufferDepth;
    if (s.mode == LightingMode::Quad) {
        p.samples = plus(gbufferSamples(d), {R::Lights});
        p.states = {fullScreen("every light")};
    }
    return p;  // forward: cleared only, nothing to count over
}

}  // namespace

PipelineSettings importedSettings(PipelineSettings s, std::string* why) {
    std::string reasons;
    if (shadesForward(s.mode)) {
        s.mode = LightingMode::Quad;
        reasons = "forward shading draws the scene's meshes and an imported G-buffer has none, so the quad pass ran";
    }
    if (s.mode == LightingMode::Prepass) {
        s.mode = LightingMode::Quad;
        reasons = "prepass draws the scene's meshes twice and an imported G-buffer has none, so the quad pass ran";
    }
    if (s.lightCubes) {
        s.lightCubes = false;
        if (!reasons.empty()) reasons += "; ";
        reasons += "the light cubes are sized to a scene, which an imported G-buffer lacks, so none were drawn";
    }
    if (why) *why = reasons;
    return s;
}

std::vector<PassDecl> framePasses(PipelineSettings const& s, bool wireframes, bool imported) {
    GBufferLayoutDesc const& d = layoutDesc(s.layout);
    bool const forward = shadesForward(s.mode);
    bool const prepass = s.mode == LightingMode::Prepass;
    bool const split = s.accumulation == LightAccumulation::Split && !forward && !prepass;
    std::vector<DrawState> const opaque =
        sceneStates("opaque surfaces", "double-sided opaque surfaces", true, Blend::Off);
    std::vector<PassDecl> out;
    if (s.mode == LightingMode::ForwardPlus) {
        // The lit target's depth first (no colour), the tiles' lists binned from it, then the
        // surfaces shaded where they equal that depth, each fragment with its tile's list.
        DepthTest const less = DepthTest::Less, lessEqual = DepthTest::LessEqual;
        out.push_back(scenePass(
            PassId::DepthPrepass, {R::Materials},
            {state("depth only", less, true, Blend::Off, FaceCull::Back, StencilUse::Off, false),
             state("double-sided depth only", less, true, Blend::Off, FaceCull::Off, StencilUse::Off, false)}));
        out.push_back(computePass(PassId::LightLists, {R::LitDepth, R::Lights}, {R::TileBins}));
        out.push_back(scenePass(
            PassId::ForwardShading, {R::Materials, R::Lights, R::TileBins},
            {state("opaque surfaces, pre-pass depth", lessEqual, false, Blend::Off, FaceCull::Back),
             state("double-sided opaque surfaces, pre-pass depth", lessEqual, false, Blend::Off, FaceCull::Off)}));
    } else if (forward) {
        out.push_back(scenePass(PassId::ForwardShading, {R::Materials, R::Lights}, opaque));
    } else if (prepass) {
        out = prepassPasses(s);
    }
    if (forward || prepass) {
        out.front().stencilWrite = true;  // cleared with the rest
        // No G-buffer of the layout in the forward modes and prepass: cleared, so the viewers show
        // that it is unused.
        for (GBufferAttachmentDesc const& a : d.attachments()) out.front().clears.push_back(slotResource(a.slot));
        out.front().clears = plus(out.front().clears, {R::Lighting, R::LitDepth});
    } else {
        bool const msaa = msaaFrame(s, imported);
        PassDecl g = declare(imported ? PassId::Import : PassId::Geometry);
        g.samples = {imported ? R::Imported : R::Materials};
        for (GBufferAttachmentDesc const& a : d.colorAttachments()) g.color.push_back(slotResource(a.slot));
        g.depthStencil = R::GBufferDepth;
        if (msaa) {
            g.color = msaaColor(d);
            g.depthStencil = R::MsaaDepth;
        }
        g.depthRead = g.depthWrite = g.stencilWrite = true;  // stencil cleared
        // The import pass writes each covered pixel's depth (gl_FragDepth) whatever is there.
        g.states =
            imported
                ? std::vector<DrawState>{state("imported surfaces", DepthTest::Always, true, Blend::Off, FaceCull::Off)}
                : opaque;
        g.clears = plus(g.color, {*g.depthStencil});
        out.push_back(std::move(g));
        if (msaa) {
            out.push_back(msaaEdgesPass(d));
            if (!lightsSamples(s)) out.push_back(msaaResolvePass(d));
        }
        if (s.mode == LightingMode::Tiled)
            out.push_back(computePass(PassId::LightLists, {R::GBufferDepth, R::Lights}, {R::TileBins}));
        if (s.mode == LightingMode::Clustered)
            out.push_back(
                computePass(PassId::LightLists, {R::GBufferDepth, R::Lights}, {R::TileBins, R::ClusterLists}));
        // msaa volumes lit from the samples: over the lit target's depth-stencil, the complex bit and
        // a resolved depth (docs/msaa.md).
        bool const msaaVolumes = msaa && lightsSamples(s) && s.mode == LightingMode::Volumes;
        if (msaaVolumes)
            out.push_back(msaaVolumeDepthPass());
        else if (s.mode == LightingMode::Volumes && lightingSamplesDepth(d))
            out.push_back(volumeDepthPass());
        out.push_back(msaaVolumes ? msaaVolumesPass(s, d) : lightingPass(s, split));
        if (msaa && !msaaVolumes && s.msaaLighting == MsaaLighting::Edges) out.push_back(lightingComplexPass(d));
        if (msaa && lightsSamples(s)) out.push_back(msaaResolvePass(d));
        if (split) {
            PassDecl c = litPass(PassId::LightCombine, plus(gbufferSamples(d), {R::DiffuseLight, R::SpecularLight}),
                                 fullScreen("combine"));
            out.push_back(std::move(c));
        }
        out.push_back(depthCopyPass(s.depthCopy));
    }
    if (!imported) {  // forward+: the blended surfaces read the tiles' lists too (docs/transparency.md)
        std::vector<Resource> samples{R::Materials, R::Lights};
        if (s.mode == LightingMode::ForwardPlus) samples.push_back(R::TileBins);
        out.push_back(scenePass(PassId::Forward, std::move(samples),
                                sceneStates("blended surfaces", "double-sided blended surfaces", false, Blend::Alpha)));
    }
    // The light targets of an earlier split frame would otherwise show in this one's views.
    if (!split && !prepass) out.front().clears = plus(out.front().clears, {R::DiffuseLight, R::SpecularLight});
    if (viewNeedsCoverage(s.view)) {
        // msaa volumes test the lit target's depth, made no copy: the counts test the resolved depth's.
        bool const resolvedCopy =
            msaaFrame(s, imported) && lightsSamples(s) && s.mode == LightingMode::Volumes && lightingSamplesDepth(d);
        if (resolvedCopy) out.push_back(volumeDepthPass());
        out.push_back(coveragePass(s));
    }
    out.push_back(displayPass(d, R::Display, prepass));
    if (s.glassOutline && !imported) out.push_back(glassOutlinePass(R::Display));
    // The overlays, onto the display image: the lit image stays the light sum.
    if (!viewShowsOverlays(s.view)) return out;
    if (s.lightCubes) {  // overlayFbo: the lit target's depth, the scene's only after the depth-copy step
        // The cubes mark the pixels they cover; the blended surfaces are drawn again there, over a
        // cube behind them (one in front has written its depth and hides them): docs/transparency.md.
        PassDecl cubes =
            overlayPass(PassId::LightCubes, {R::Lights, R::Materials}, R::LitDepth,
                        state("cubes", DepthTest::Less, true, Blend::Off, FaceCull::Back, StencilUse::MarkCovered));
        cubes.stencilRead = cubes.stencilWrite = true;
        for (DrawState glass : sceneStates("blended surfaces over the cubes",
                                           "double-sided blended surfaces over the cubes", false, Blend::Alpha)) {
            glass.stencil = StencilUse::Covered;
            cubes.states.push_back(glass);
        }
        out.push_back(std::move(cubes));
    }
    if (wireframes)  // the scene's depth without the depth-copy step: the G-buffer's (forward: its own)
        out.push_back(overlayPass(PassId::Wireframes, {R::Lights, R::VolumeInstances},
                                  forward || prepass ? R::LitDepth : R::GBufferDepth,
                                  state("lines", DepthTest::LessEqual, false, Blend::Off, FaceCull::Off)));
    return out;
}

PassDecl readbackPass(bool stencil) {
    PassDecl p;
    p.customName = stencil ? "readback_stencil" : "readback_depth";
    p.color = {R::Readback};
    if (!stencil) {
        p.samples = {R::GBufferDepth};
        p.states = {fullScreen("depth texels")};
        return p;
    }
    p.depthStencil = R::GBufferDepth;  // attached for its stencil, not sampled
    p.stencilRead = true;
    static constexpr std::array<std::string_view, 8> kBits{"stencil bit 0", "stencil bit 1", "stencil bit 2",
                                                           "stencil bit 3", "stencil bit 4", "stencil bit 5",
                                                           "stencil bit 6", "stencil bit 7"};
    for (int bit = 0; bit < 8; ++bit) {
        DrawState s =
            state(kBits[std::size_t(bit)], DepthTest::Off, false, Blend::Add, FaceCull::Off, StencilUse::EqualBits);
        s.stencilRef = 1 << bit;
        p.states.push_back(s);
    }
    return p;
}

std::vector<PassDecl> viewPasses(PipelineSettings const& s) {
    GBufferLayoutDesc const& d = layoutDesc(s.layout);
    std::vector<PassDecl> out;
    if (viewNeedsCoverage(s.view)) {
        if (s.mode == LightingMode::Volumes && lightingSamplesDepth(d)) out.push_back(volumeDepthPass());
        out.push_back(coveragePass(s));
    }
    out.push_back(displayPass(d, R::View, s.mode == LightingMode::Prepass));
    if (s.glassOutline) out.push_back(glassOutlinePass(R::View));
    return out;
}

std::vector<PassDecl> passesUntil(std::vector<PassDecl> passes, PassId stop) {
    auto const at = [&](PassId id) {
        return std::find_if(passes.begin(), passes.end(), [id](PassDecl const& p) { return p.id == id; });
    };
    auto const last = at(stop);
    if (last == passes.end() || last + 1 == passes.end()) return passes;  // nothing to skip
    auto const display = at(PassId::Display);  // always there (framePasses); only overlays follow it
    if (last >= display) {                     // the display itself or an overlay: nothing after it runs
        passes.erase(last + 1, passes.end());
    } else {
        PassDecl shown = std::move(*display);
        passes.erase(last + 1, passes.end());
        passes.push_back(std::move(shown));
    }
    passes.front().clears =
        plus(passes.front().clears, {R::Lighting, R::LitDepth, R::DiffuseLight, R::SpecularLight, R::Coverage});
    return passes;
}

std::optional<std::string> stopAfterError(std::string_view name, std::span<PassDecl const> passes) {
    if (std::any_of(passes.begin(), passes.end(), [name](PassDecl const& p) { return p.name() == name; }))
        return std::nullopt;
    std::string known;
    for (std::size_t i = 0; i < passes.size(); ++i)
        known += std::string(i == 0 ? "" : i + 1 == passes.size() ? " and " : ", ") + std::string(passes[i].name());
    std::string const why = passFromName(name) ? "this frame does not run it" : "no pass has that name";
    return "cannot stop after '" + std::string(name) + "': " + why + "; this frame's passes are " + known;
}

std::vector<FeedbackLoop> feedbackLoops(std::span<PassDecl const> passes) {
    std::vector<FeedbackLoop> out;
    for (PassDecl const& p : passes) {
        if (p.kind == PassKind::Compute) continue;  // no framebuffer in a dispatch
        for (Resource r : p.samples) {
            bool const attached = std::find(p.color.begin(), p.color.end(), r) != p.color.end() || p.depthStencil == r;
            if (attached) out.push_back({p.id, r});
        }
    }
    return out;
}

}  // namespace gbl
