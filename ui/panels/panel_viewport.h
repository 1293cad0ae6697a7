// Viewport window: the live frame, with camera drags, picking and the view selector.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>
#include "model/ab_accumulate.h"
#include "model/ab_compare.h"
#include "model/viewer_tools.h"
#include "model/viewport_state.h"

namespace gbl::ui {

// texture: the renderer's final image (0 while the targets are 0x0); textureSize its size.
// selectedLight: where the selected light's centre falls in the image (0..1, top-left origin),
// when it is in front of the camera; a ring marks it so a click on a cube visibly selects it.
// litPin: the "Pin lit" / "Diff" controls; the caller passes the diff heat map as texture while
// litPin.showDiff has one.
// The teaching row: the light-by-light scrubber and the A/B comparison, with side B's image and
// the |A - B| heat map (ab_frame.h).
struct ViewportTeaching {
    AbState& ab;
    AccumulateState& accumulate;
    int lightCount = 0;
    std::string kthLightName;  // the light the scrubber stops at
    PipelineSettings settingsB;
    unsigned textureB = 0;
    unsigned diffTexture = 0;
};
// tools: the viewer tools while the view is a G-buffer attachment; the caller passes their view
// (serviceViewportTools) as texture while they are open.
// lockedPixel: the pixel inspector's locked pixel (renderer pixels, top-left origin), marked.
// overviewTextures: the attachment overview's cells (serviceOverview), shown instead of the frame
// while state.overview is on.
void drawViewportPanel(ViewportState& state, PipelineSettings& settings, LitPin& litPin, ViewportTools& tools,
                       unsigned texture, glm::ivec2 textureSize, std::optional<glm::vec2> selectedLight = std::nullopt,
                       ViewportTeaching* ab = nullptr, std::optional<glm::ivec2> lockedPixel = std::nullopt,
                       std::span<unsigned const> overviewTextures = {});

}  // namespace gbl::ui
