// Coverage counts pass.
#include "passes/coverage.h"

namespace gbl {

CoverageOutput coveragePass(CoverageInput const& in, CoverageConfig const& c) {
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.id());
    glViewport(0, 0, c.tiled.width, c.tiled.height);  // cleared by the executor (PassDecl::clears)
    bool const tiles =
        c.view == DebugView::TileLights || c.mode == LightingMode::Tiled || c.mode == LightingMode::ForwardPlus;
    if (tiles) {
        if (in.tiled && in.tiledBin && in.bins) {
            LightingTiledConfig t = c.tiled;
            t.shade = false;
            t.coverage = true;
            lightingTiledPass({in.deferred, *in.tiled, *in.tiledBin, *in.bins, in.hdr, in.hdr, in.coverage, in.caps},
                              t);
        }
    } else if (c.mode == LightingMode::Volumes) {
        if (in.volumes && in.volumeCoverage && in.volumeStencil) {
            drawLightVolumes({in.deferred, *in.volumes, *in.volumeCoverage, *in.volumeStencil}, c.viewProj, c.cull,
                             c.states);
        }
    } else if (c.mode == LightingMode::Quad) {
        applyGroup(c.states, 0);
        in.allLights.use();
        bindDeferredInputs(in.allLights, in.deferred);
        in.triangle.draw();
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return {in.coverage};
}

}  // namespace gbl
