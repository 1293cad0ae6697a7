// G-buffer window: one live viewer per attachment (position, normal, albedo, specular, depth),
// side by side, each with channel isolation, range remap, zoom and pan.
#pragma once

#include "model/viewer_state.h"

namespace gbl::ui {

// textures[i]: the view target drawn for viewer i this frame (0 when there is none yet).
void drawGBufferPanel(GBufferPanelState& state, std::array<unsigned, 5> const& textures, glm::ivec2 imageSize);

}  // namespace gbl::ui
