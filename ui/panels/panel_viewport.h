// Viewport window: the live frame, with camera drags, picking and the view selector.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include "model/viewer_tools.h"
#include "model/viewport_state.h"

namespace gbl::ui {

// texture: the renderer's final image (0 while the targets are 0x0); textureSize its size.
// selectedLight: where the selected light's centre falls in the image (0..1, top-left origin),
// when it is in front of the camera; a ring marks it so a click on a cube visibly selects it.
// litPin: the "Pin lit" / "Diff" controls; the caller passes the diff heat map as texture while
// litPin.showDiff has one. tools: the viewer tools while the view is a G-buffer attachment; the
// caller passes their view (serviceViewportTools) as texture while they are open.
void drawViewportPanel(ViewportState& state, PipelineSettings& settings, LitPin& litPin, ViewportTools& tools,
                       unsigned texture, glm::ivec2 textureSize, std::optional<glm::vec2> selectedLight = std::nullopt);

}  // namespace gbl::ui
