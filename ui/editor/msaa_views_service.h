// The editor loop's side of the MSAA views (model/msaa_views.h, issue 47): the complex-pixel
// overlay and the samples-that-differ heat map made from the renderer's read-backs, the selected
// samples kept in range, and the pixel inspector's samples.
#pragma once

#include "gl/texture.h"
#include "model/editor_state.h"
#include "renderer.h"

#include <optional>

namespace gbl::ui {

struct MsaaViewsGpu {
    gl::Texture overlay;  // complexOverlayRgba
    gl::Texture heat;     // samplesHeatRgba
    // A new frame makes both stale; each is remade when next shown.
    bool overlayStale = true;
    bool heatStale = true;
    std::optional<double> countedShare;  // the complex share from the counts, where no edges pass counted
};

// Call after the frame (and before the panels): sets state.viewport.msaa's samples, share and
// textures and every viewer's sample in range for `stats`, the frame shown; `rendered`: it is new.
void serviceMsaaViews(EditorState& state, Renderer& renderer, FrameStats const& stats, bool rendered,
                      MsaaViewsGpu& gpu);
// The pixel inspector's samples at its pixel (empty without msaa): `samples` per pixel.
void sampleMsaaPixel(PixelInspectorState& inspector, Renderer& renderer, int samples);

}  // namespace gbl::ui
