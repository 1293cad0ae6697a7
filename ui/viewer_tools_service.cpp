// Read-backs, requests and heat-map uploads of the viewer tools.
#include "viewer_tools_service.h"

#include "model/viewer_tools.h"

#include <epoxy/gl.h>

namespace gbl::ui {

// Scale: the threshold when one is set (so "over" reads as the top of the ramp), else the max.
void uploadDiff(gl::Texture& tex, DiffStats const& diff, float threshold, bool changed) {
    int const w = diff.diff.width, h = diff.diff.height;
    if (!tex || tex.width() != w || tex.height() != h) {
        tex = gl::Texture::create2D(GL_RGBA8, w, h, "viewer diff");
        tex.setFilter(GL_NEAREST, GL_NEAREST);
        changed = true;
    }
    if (!changed) return;
    std::vector<std::uint8_t> const rgba = diffHeatmap(diff, threshold > 0.0f ? threshold : diff.max);
    // Rows top to bottom in memory; the views draw textures with v flipped (GL's bottom-up rows).
    glBindTexture(GL_TEXTURE_2D, tex.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    for (int y = 0; y < h; ++y)
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, h - 1 - y, w, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                        rgba.data() + std::size_t(y) * std::size_t(w) * 4);
    glBindTexture(GL_TEXTURE_2D, 0);
}

void serviceViewerTools(EditorState& state, Renderer& renderer, long frame, std::array<unsigned, 5>& textures,
                        ViewerToolsGpu& gpu) {
    GBufferPanelState& panel = state.gbuffer;
    if (renderer.width() <= 0 || renderer.height() <= 0) return;
    for (std::size_t i = 0; i < panel.viewers.size(); ++i) {
        ViewerState& v = panel.viewers[i];
        ViewerData& d = panel.data[i];
        if (!viewerNeedsData(panel, i)) continue;
        bool diffChanged = false;
        if (viewerDataDue(v, d, frame)) {
            bool const ownPlanes = v.kind == ViewerKind::Depth && !v.cameraClipPlanes;
            float const nearPlane = ownPlanes ? v.nearPlane : state.camera.nearPlane;
            float const farPlane = ownPlanes ? v.farPlane : state.camera.farPlane;
            setViewerValues(
                v, d, viewerValues(v, renderer.readAttachment(viewerAttachment(v.kind)), nearPlane, farPlane), frame);
            diffChanged = v.showDiff && d.pinned;
        } else {
            diffChanged = updateViewerStats(v, d);
        }
        if (!v.showDiff || !d.diff.comparable) continue;
        uploadDiff(gpu.diff[i], d.diff, v.diffThreshold, diffChanged);
        textures[i] = gpu.diff[i].id();
    }
}

unsigned serviceLitPin(LitPin& pin, Renderer& renderer, long frame, ViewerToolsGpu& gpu) {
    if (renderer.width() <= 0 || renderer.height() <= 0) return 0;
    bool const due = litPinDue(pin, frame);
    if (due) setLitValues(pin, renderer.readAttachment(Attachment::Lighting), frame);
    if (!pin.showDiff || !pin.diff.comparable) return 0;
    uploadDiff(gpu.litDiff, pin.diff, pin.diffThreshold, due);
    return gpu.litDiff.id();
}

}  // namespace gbl::ui
