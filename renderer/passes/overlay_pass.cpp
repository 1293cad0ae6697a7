// Debug data and overlays of the lighting modes: the coverage counts behind the heat map and
// the lights-per-tile view, and the light-volume wireframes.
#include "renderer_impl.h"

namespace gbl {

namespace {
bool needsCoverage(DebugView v) { return v == DebugView::Heatmap || v == DebugView::TileLights; }
}  // namespace

// --- coverage ----------------------------------------------------------------------------------
// targets.coverage: x = lights whose shading ran at the pixel (volume fragments, tile-list
// entries, or every light for quad), y = lights that actually reached the surface there.
// The lights-per-tile view always shows the tiled mode's lists (when compute exists).
void RendererImpl::coveragePass(FrameContext const& f) {
    initLightVolumes();
    glBindFramebuffer(GL_FRAMEBUFFER, targets.coverageFbo.id());
    glViewport(0, 0, targets.width, targets.height);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    bool const tiles = f.settings.view == DebugView::TileLights || f.settings.mode == LightingMode::Tiled;
    if (tiles) {
        if (caps.computeShaders) lightingTiledPass(f, false, true);
    } else if (f.settings.mode == LightingMode::Volumes) {
        // The instance list is this frame's: the volumes lighting pass built it.
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE);
        drawLightVolumes(f, shaders.get("light_volume_coverage"), f.settings.cull);
        glDisable(GL_BLEND);
    } else if (f.settings.mode == LightingMode::Quad) {
        glDisable(GL_DEPTH_TEST);
        gl::Program const& p = shaders.get("coverage_all_lights");
        p.use();
        bindLightingInputs(p, f);
        glBindVertexArray(emptyVao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
    }
    // Forward mode has no G-buffer to count over: the counts stay zero.
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    coverageValid = true;
}

void RendererImpl::ensureCoverage(DebugView view) {
    if (!needsCoverage(view) || targets.empty()) return;
    if (coverageValid && lastFrame.settings.view == view) return;
    // The light buffer and the volume instance list still hold the last frame's lights.
    FrameContext f = lastFrame;
    f.settings.view = view;
    coveragePass(f);
    lastFrame.settings.view = view;
}

// --- wireframes ----------------------------------------------------------------------------------
// Each light's enclosing sphere (the very mesh the volumes pass draws) as lines in the light's
// colour, depth-tested against the scene and drawn into the HDR image.
void RendererImpl::volumeWireframesPass(FrameContext const& f) {
    prepareVolumeInstances(f);
    int const total = volumes.outsideCount + volumes.insideCount;
    if (total == 0) return;
    // Forward mode leaves the G-buffer empty, so its own depth (in litFbo) is the scene's.
    bool const forward = f.settings.mode == LightingMode::Forward;
    glBindFramebuffer(GL_FRAMEBUFFER, forward ? targets.litFbo.id() : targets.volumeFbo.id());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    gl::Program const& p = shaders.get("light_volume_wire");
    p.use();
    bindLightingInputs(p, f);
    glActiveTexture(GL_TEXTURE4);
    glBindTexture(GL_TEXTURE_BUFFER, volumes.instancesTbo.id());
    glActiveTexture(GL_TEXTURE0);
    p.set("uInstances", 4);
    p.set("uViewProj", f.viewProj);
    p.set("uEnclosingScale", volumes.enclosingScale);
    p.set("uFirstInstance", 0);
    p.set("uWireIntensity", 2.0f);
    glBindVertexArray(volumes.lineVao.id());
    glDrawElementsInstanced(GL_LINES, volumes.lineIndexCount, GL_UNSIGNED_INT, nullptr, total);
    glBindVertexArray(0);
    glEnable(GL_CULL_FACE);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
}

}  // namespace gbl
