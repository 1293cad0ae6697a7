// Lighting modes within the frame: the light lists of tiled and clustered, the lighting pass of
// each mode and the coverage counts behind the heat-map views.
#include "renderer_impl.h"

#include "passes/coverage.h"
#include "passes/light_volumes.h"
#include "passes/lighting_quad.h"
#include "passes/lighting_tiled.h"

namespace gbl {

LightingClusteredInput RendererImpl::clusteredInput(FrameContext const& f) {
    return {deferredInputs(f),
            shaders.get(ProgramId::ClusterBuild),
            binPrograms(ProgramId::ClusterBin),
            tileBins,
            shaders.get(ProgramId::ClusterShade),
            clusters,
            lightingImage(f),
            targets.specularLight,
            targets.coverage};
}

LightingClusteredConfig RendererImpl::clusteredConfig(FrameContext const& f, bool shade) const {
    return {f.view, f.projection, targets.width, targets.height, f.camera.nearPlane, f.camera.farPlane, shade, !shade};
}

TileBinPrograms RendererImpl::binPrograms(ProgramId bin) const {
    return {shaders.get(ProgramId::TileDepth), shaders.get(bin)};
}

// Tiled bins each tile's candidate lights, clustered also builds its clusters' lists: a pass of
// their own, so bench reports the lists apart from the shading that reads them.
void RendererImpl::buildLightLists(FrameContext const& f) {
    if (f.settings.mode == LightingMode::Clustered) {
        clusterListsPass(clusteredInput(f), clusteredConfig(f, true));
        return;
    }
    tileBinPass({binPrograms(ProgramId::TileBin), lights, targets.gbuffer.depth, tileBins},
                {f.view, f.projection, targets.width, targets.height, f.camera.nearPlane, f.camera.farPlane});
}

void RendererImpl::runLighting(FrameContext const& f) {
    DeferredInputs const deferred = deferredInputs(f);
    switch (f.settings.mode) {
        case LightingMode::Volumes:
            lightingVolumesPass(
                {deferred, volumes, shaders.get(ProgramId::LightingQuad), shaders.get(ProgramId::LightVolume),
                 shaders.get(ProgramId::LightVolumeStencil), triangle, volumeTarget(f)},
                {f.viewProj, f.settings.cull});
            break;
        case LightingMode::Tiled:  // the tiles' candidates were binned in the frame's light_lists pass
            lightingTiledPass({deferred, shaders.get(ProgramId::LightingTiled), binPrograms(ProgramId::TileBin),
                               tileBins, lightingImage(f), targets.specularLight, targets.coverage},
                              {f.view, f.projection, targets.width, targets.height, f.camera.nearPlane,
                               f.camera.farPlane, true, false, true});
            break;
        case LightingMode::Clustered:  // the lists were built in the frame's light_lists pass
            clusterShadePass(clusteredInput(f), clusteredConfig(f, true));
            break;
        default:
            lightingQuadPass({deferred, shaders.get(ProgramId::LightingQuad), triangle, quadTarget(f)});
            break;
    }
}

void RendererImpl::runCoverage(FrameContext const& f) {
    coverageView = f.settings.view;
    coverageMode = f.settings.mode;
    if (f.settings.mode == LightingMode::Clustered && f.settings.view != DebugView::TileLights) {
        // x = the pixel's cluster list, y = lights that lit it: the heat map's scale, as tiles.
        glBindFramebuffer(GL_FRAMEBUFFER, targets.coverageFbo.id());
        glClearColor(0, 0, 0, 0);
        glClear(GL_COLOR_BUFFER_BIT);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        clusterListsPass(clusteredInput(f), clusteredConfig(f, false));
        clusterShadePass(clusteredInput(f), clusteredConfig(f, false));
        return;
    }
    bool const tiles = f.settings.view == DebugView::TileLights || f.settings.mode == LightingMode::Tiled;
    bool const volumeCounts = !tiles && f.settings.mode == LightingMode::Volumes && volumesReady();
    if (volumeCounts) prepareVolumeInstances(volumes, {f.camera, f.aspect, f.lights});
    bool const tiled = tiles && tiledReady();
    LightingTiledConfig const t{
        f.view, f.projection, targets.width, targets.height, f.camera.nearPlane, f.camera.farPlane, false, true};
    TileBinPrograms const bin = binPrograms(ProgramId::TileBin);
    coveragePass(
        {deferredInputs(f), triangle, shaders.get(ProgramId::CoverageAllLights), volumeCounts ? &volumes : nullptr,
         volumeCounts ? &shaders.get(ProgramId::LightVolumeCoverage) : nullptr,
         volumeCounts ? &shaders.get(ProgramId::LightVolumeStencil) : nullptr,
         tiled ? &shaders.get(ProgramId::LightingTiled) : nullptr, tiled ? &bin : nullptr, tiled ? &tileBins : nullptr,
         targets.coverageFbo, targets.coverage, targets.lighting},
        {f.settings.mode, f.settings.cull, f.settings.view, t, f.viewProj});
}

}  // namespace gbl
