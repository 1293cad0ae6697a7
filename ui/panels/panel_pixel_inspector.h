// Pixel inspector window: stored values of one pixel and what each light added.
#pragma once

#include "model/pixel_inspector_state.h"

namespace gbl::ui {

void drawPixelInspectorPanel(PixelInspectorState& state);

}  // namespace gbl::ui
