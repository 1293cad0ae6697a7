// Viewport window: the live frame at the window's size, what it shows, and the mouse input
// that drives the camera, the pixel inspector and light picking.
#pragma once

#include "pipeline_settings.h"

#include <glm/glm.hpp>

#include <optional>

namespace gbl::ui {

struct ViewportState {
    glm::ivec2 size{0};  // image area in framebuffer pixels; the renderer follows it next frame
    bool hovered = false;
    std::optional<glm::ivec2> hoverPixel;  // renderer pixel under the mouse, origin top-left
    std::optional<glm::ivec2> clickPixel;  // a left click that was not a drag, this frame
    glm::vec2 orbitDrag{0.0f};             // this frame's drags, in pixels (see CameraInput)
    glm::vec2 lookDrag{0.0f};
    glm::vec2 panDrag{0.0f};
    float wheel = 0.0f;
    bool frameRequested = false;           // the Frame button (the F key is read by the loop)
};

// texture: the renderer's final image (0 while the targets are 0x0); textureSize its size.
// selectedLight: where the selected light's centre falls in the image (0..1, top-left origin),
// when it is in front of the camera; a ring marks it so a click on a cube visibly selects it.
void drawViewportPanel(ViewportState& state, PipelineSettings& settings, unsigned texture, glm::ivec2 textureSize,
                       std::optional<glm::vec2> selectedLight = std::nullopt);

}  // namespace gbl::ui
