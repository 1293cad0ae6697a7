// The MSAA views' read-backs and textures (msaa_views_service.h).
#include "msaa_views_service.h"

#include "editor/viewer_tools_service.h"
#include "model/msaa_views.h"

namespace gbl::ui {

void serviceMsaaViews(EditorState& state, Renderer& renderer, FrameStats const& stats, bool rendered,
                      MsaaViewsGpu& gpu) {
    MsaaViewState& m = state.viewport.msaa;
    int const samples = stats.msaaUsed != Msaa::Off ? renderer.msaaSampleCount() : 0;
    m.samples = samples;
    state.gbuffer.msaaSamples = samples;
    // The viewport tools' kind follows the view: a kind without samples (depth, lit) shows all.
    auto const keep = [samples](ViewerState& v) {
        v.sample = viewerSampleSlot(v.kind) ? clampSample(v.sample, samples) : -1;
    };
    for (ViewerState& v : state.gbuffer.viewers) keep(v);
    keep(state.viewportTools.viewer);
    state.inspector.msaaSample = clampSample(state.inspector.msaaSample, samples);
    if (rendered) {
        gpu.overlayStale = gpu.heatStale = true;
        gpu.countedShare.reset();
    }
    m.overlayTexture = m.heatTexture = 0;
    m.complexShare = stats.complexPixelShare;
    if (samples <= 0) return;
    // The edges pass marks the complex pixels itself; the other strategies have no such pass, so
    // the overlay takes them from the counts (2 or more surfaces: the same test, msaa_edges.glsl).
    bool const edgesMask = stats.complexPixelShare.has_value();
    bool const needCounts = (m.samplesHeat && gpu.heatStale) || (m.complexOverlay && gpu.overlayStale && !edgesMask) ||
                            (!edgesMask && !gpu.countedShare && (m.complexOverlay || m.samplesHeat));
    FloatImage counts;
    if (needCounts) counts = renderer.msaaDistinctSampleCounts(state.camera.position);
    if (m.samplesHeat && gpu.heatStale && !counts.pixels.empty()) {
        uploadPicture(gpu.heat, counts.width, counts.height, samplesHeatRgba(counts), "msaa samples heat map");
        gpu.heatStale = false;
    }
    if (m.complexOverlay && gpu.overlayStale) {
        FloatImage const mask = edgesMask ? renderer.readAttachment(Attachment::ComplexPixels)
                                          : (counts.pixels.empty() ? FloatImage{} : complexFromCounts(counts));
        if (!mask.pixels.empty()) {
            uploadPicture(gpu.overlay, mask.width, mask.height, complexOverlayRgba(mask), "msaa complex overlay");
            gpu.overlayStale = false;
        }
    }
    if (!counts.pixels.empty()) gpu.countedShare = maskShare(complexFromCounts(counts));
    if (!m.complexShare) m.complexShare = gpu.countedShare;
    if (m.samplesHeat && gpu.heat) m.heatTexture = gpu.heat.id();
    if (m.complexOverlay && gpu.overlay) m.overlayTexture = gpu.overlay.id();
}

void sampleMsaaPixel(PixelInspectorState& inspector, Renderer& renderer, int samples) {
    inspector.msaaSamples.clear();
    if (samples <= 0 || !inspector.pixel) return;
    glm::ivec4 const rect(inspector.pixel->x, inspector.pixel->y, 1, 1);
    auto const at = [&](GBufferSlot slot, int k) {
        FloatImage const one = renderer.readMsaaDecodedSample(slot, k, rect);
        return one.pixels.size() == 4 ? glm::vec4(one.at(0, 0, 0), one.at(0, 0, 1), one.at(0, 0, 2), one.at(0, 0, 3))
                                      : glm::vec4(0.0f);
    };
    for (int k = 0; k < samples; ++k)
        inspector.msaaSamples.push_back({at(GBufferSlot::Position, k), at(GBufferSlot::Normal, k),
                                         at(GBufferSlot::AlbedoSpec, k), at(GBufferSlot::Emissive, k)});
}

}  // namespace gbl::ui
