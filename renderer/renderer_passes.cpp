// The executor: each declared pass (core/frame_passes.h) run by the function its id names, with the
// targets its declaration names (gpu/frame_resources.h), its clears done first and its draw states
// handed to it. The run functions of the passes that are not lighting modes.
#include "renderer_impl.h"
#include "renderer_test_access.h"

#include "passes/depth_copy.h"
#include "passes/forward.h"
#include "passes/geometry.h"
#include "passes/light_combine.h"
#include "passes/light_cubes.h"
#include "passes/view.h"
#include "passes/volume_depth.h"
#include "passes/wireframes.h"

#include "core/tile_math.h"

#include <algorithm>
#include <array>

namespace gbl {

RendererImpl::RunFunction RendererImpl::runFunction(PassId id) {
    // PassId -> run function, in PassId's order.
    static constexpr std::array<RunFunction, kPassNames.size()> kRun{
        &RendererImpl::runForwardShading, &RendererImpl::runGeometry,        &RendererImpl::runLightLists,
        &RendererImpl::runVolumeDepth,    &RendererImpl::runLighting,        &RendererImpl::runLightCombine,
        &RendererImpl::runDepthCopy,      &RendererImpl::runForward,         &RendererImpl::runLightCubes,
        &RendererImpl::runWireframes,     &RendererImpl::runCoverage,        &RendererImpl::runDisplay,
        &RendererImpl::runImport,         &RendererImpl::runGlassOutline,    &RendererImpl::runDepthPrepass,
        &RendererImpl::runMsaaEdges,      &RendererImpl::runLightingComplex, &RendererImpl::runMsaaResolve,
        &RendererImpl::runThinGBuffer,    &RendererImpl::runPrepassShading};
    return kRun[std::size_t(id)];
}

void RendererImpl::runPasses(std::span<PassDecl const> passes, FrameRecord& frame, FrameResources const& io) {
    for (PassDecl const& decl : passes) {
        {
            PassScope const scope(timer, frame, decl);
            if (passObserver) passObserver(decl);
            io.clear(decl.clears);
            PassRun const run{decl, io, decl.kind == PassKind::Compute ? nullptr : &io.framebuffer(decl)};
            bool const counted = fragmentQuery && countsFragments(decl.id);
            if (counted) fragmentQuery.begin();
            auto const extra = std::find_if(extraPasses.begin(), extraPasses.end(), [&](ExtraPass const& e) {
                return !decl.customName.empty() && e.decl.customName == decl.customName;
            });
            if (extra != extraPasses.end())
                extra->run(run);
            else
                (this->*runFunction(decl.id))(frame, run);
            if (counted) fragmentQuery.end();
        }
        if (frameTestHook && !frame.view && &decl == &passes.front()) frameTestHook();  // untimed, between passes
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// forward, forward+: the surfaces `filter` keeps, shaded light by light. Forward+ (its declaration
// samples the tile lists) draws with the list-reading build, over the binning grid (the blended
// surfaces' lists binned from the near plane, passes/tile_bins.h).
void RendererImpl::runForwardFiltered(FrameRecord& frame, PassRun const& r, MaterialFilter filter, bool backToFront) {
    bool const listed =
        std::find(r.decl.samples.begin(), r.decl.samples.end(), Resource::TileBins) != r.decl.samples.end();
    forwardPass({scene,
                 lights,
                 shaders.get(listed ? ProgramId::ForwardPlus : ProgramId::Forward),
                 {*r.fbo, r.io.texture(r.decl.color.front())},
                 listed ? &tileBins : nullptr},
                {filter, frame.f.viewProj, frame.shading, frame.f.settings.normalMaps, r.decl.states, backToFront,
                 tileGrid(targets.width, targets.height).tilesX});
}

void RendererImpl::runForwardShading(FrameRecord& frame, PassRun const& r) {
    runForwardFiltered(frame, r, MaterialFilter::Opaque, false);
}

// forward+: the opaque surfaces' depth alone, drawn with the geometry program into the lit
// target's depth (colour writes off in its draw state; the alpha mask applied as in the G-buffer).
void RendererImpl::runDepthPrepass(FrameRecord& frame, PassRun const& r) {
    geometryPass({scene, shaders.get(ProgramId::Geometry), *r.fbo}, {frame.f.viewProj, false, r.decl.states});
}

void RendererImpl::runForward(FrameRecord& frame, PassRun const& r) {
    runForwardFiltered(frame, r, MaterialFilter::Blended, true);  // back to front: the over operator
}

// The blended surfaces hatched in one colour over the view (shaders/glass_outline.frag).
void RendererImpl::runGlassOutline(FrameRecord& frame, PassRun const& r) {
    glBindFramebuffer(GL_FRAMEBUFFER, r.fbo->id());
    gl::Program const& program = shaders.get(ProgramId::GlassOutline);
    program.use();
    program.set("uViewProj", frame.f.viewProj);
    drawScene(scene, program, MaterialFilter::Blended, false, r.decl.states);  // applies its one group
}

void RendererImpl::runGeometry(FrameRecord& frame, PassRun const& r) {
    bool const msaa = r.decl.depthStencil == Resource::MsaaDepth;  // the multisampled G-buffer
    geometryPass({scene, shaders.get(ProgramId::Geometry), msaa ? r.io.targets.msaa.gbuffer.fbo : *r.fbo},
                 {frame.f.viewProj, frame.f.settings.normalMaps, r.decl.states});
}

void RendererImpl::runImport(FrameRecord&, PassRun const& r) {
    importPass({*imported, shaders.get(ProgramId::Import), triangle, *r.fbo},
               {r.io.targets.width, r.io.targets.height, r.decl.states});
}

void RendererImpl::runVolumeDepth(FrameRecord&, PassRun const& r) {
    // The G-buffer's depth-stencil, or in msaa volumes frames the multisampled depth alone (as declared).
    volumeDepthPass({r.io.blitSource(r.decl.samples.front()), *r.fbo},
                    {r.io.targets.width, r.io.targets.height, r.decl.stencilWrite});
}

void RendererImpl::runLightCombine(FrameRecord& frame, PassRun const& r) {
    lightCombinePass({r.io.gbuffer(),
                      shadingUniforms(frame.f),
                      r.io.texture(Resource::DiffuseLight),
                      r.io.texture(Resource::SpecularLight),
                      shaders.get(ProgramId::LightCombine),
                      triangle,
                      {*r.fbo, r.io.texture(r.decl.color.front())},
                      r.decl.states});
}

void RendererImpl::runDepthCopy(FrameRecord& frame, PassRun const& r) {
    depthCopyPass({r.io.blitSource(Resource::GBufferDepth), r.io.texture(Resource::GBufferDepth),
                   shaders.get(ProgramId::DepthCopy), triangle, *r.fbo},
                  {frame.f.settings.depthCopy, r.io.targets.width, r.io.targets.height, r.decl.states});
}

void RendererImpl::runDisplay(FrameRecord& frame, PassRun const& r) {
    FrameContext const& f = frame.f;
    ViewParams display;
    display.view = f.settings.view;
    if (frame.view) display = *frame.view;
    // A prepass frame's display declares its thin G-buffer (core/frame_passes.cpp, displayPass).
    bool const thin =
        std::find(r.decl.samples.begin(), r.decl.samples.end(), Resource::PrepassNormal) != r.decl.samples.end();
    viewPass({r.io.gbuffer(), r.io.texture(Resource::Lighting), r.io.texture(Resource::Coverage),
              r.io.texture(Resource::DiffuseLight), r.io.texture(Resource::SpecularLight), viewProgram(f.settings.view),
              triangle, *r.fbo, thin ? &r.io.texture(Resource::PrepassNormal) : nullptr,
              thin ? &r.io.texture(Resource::LitDepth) : nullptr},
             {display, f.settings.tonemap, f.settings.exposure, f.camera.nearPlane, f.camera.farPlane,
              r.io.targets.width, r.io.targets.height, frame.shading.inverseViewProj, r.decl.states});
}

// The overlays, drawn onto the display image so the lit image stays the light sum (what
// lighting.exr exports and light-by-light accumulation adds up); the tonemap is the display
// pass's, so they look as they did when they were drawn into the lit image.
void RendererImpl::runLightCubes(FrameRecord& frame, PassRun const& r) {
    // Against the lit target's depth: the scene's only when the depth-copy step filled it (the
    // depth_blit lesson: without it, the cubes show through walls).
    DisplayTonemap const tonemap{frame.f.settings.tonemap, frame.f.settings.exposure};
    lightCubesPass({lights, shaders.get(ProgramId::LightCube), cubeVao, *r.fbo},
                   {frame.f.viewProj, lightCubeHalfSize(), tonemap, std::span(r.decl.states).first(1)});
    // The blended surfaces over the cubes' pixels (the stencil the cubes marked), farthest first,
    // lit by every light and tonemapped: a cube behind a pane is seen through it.
    if (r.decl.states.size() < 3 || !hasBlended(scene) || lights.count == 0) return;
    gl::Program const& glass = shaders.get(ProgramId::GlassOverCubes);
    glass.use();
    setTonemapUniforms(glass, tonemap);
    forwardPass({scene, lights, glass, {*r.fbo, r.io.texture(Resource::Display)}},
                {MaterialFilter::Blended, frame.f.viewProj, frame.shading, frame.f.settings.normalMaps,
                 std::span(r.decl.states).subspan(1), true});
}

void RendererImpl::runWireframes(FrameRecord& frame, PassRun const& r) {
    FrameContext const& f = frame.f;
    WireframesConfig wire;
    wire.viewProj = f.viewProj;
    wire.tonemap = {f.settings.tonemap, f.settings.exposure};
    wire.states = r.decl.states;
    if (frame.outline >= 0) {
        auto const slot = volumeInstanceSlot(f.lights, frame.outline, f.camera, f.aspect, volumes.enclosingScale,
                                             volumes.coneRadialScale, volumes.volumeScale);
        wire.firstInstance = slot.value_or(0);
        wire.count = slot ? 1 : 0;
    }
    wireframesPass({lights, volumes, shaders.get(ProgramId::LightVolumeWire), *r.fbo}, wire);
}

}  // namespace gbl
