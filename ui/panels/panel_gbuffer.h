// G-buffer window: one live viewer per attachment (position, normal, albedo, specular, depth),
// side by side, each with channel isolation, range remap, zoom and pan.
#pragma once

#include "model/viewer_state.h"

#include <optional>

namespace gbl::ui {

// textures[i]: the view target drawn for viewer i this frame (0 when there is none yet);
// lockedPixel: the pixel inspector's locked pixel, marked in every viewer.
void drawGBufferPanel(GBufferPanelState& state, std::array<unsigned, 5> const& textures, glm::ivec2 imageSize,
                      std::optional<glm::ivec2> lockedPixel = std::nullopt);

}  // namespace gbl::ui
