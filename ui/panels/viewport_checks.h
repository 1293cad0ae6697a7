// An open G-buffer's check findings in the viewport's toolbar (docs/import.md, "Checks"): a button
// that says how many, and its list: each finding's pixels, share and likely cause (a click on one
// marks its pixels over the image), then each attachment's precision note.
#pragma once

#include "model/viewport_state.h"

namespace gbl::ui {

// Draws nothing while no G-buffer is open; records the button's and first finding's rectangles
// and the precision lines drawn in `state` for the frame log.
void drawChecksButton(ViewportState& state);

}  // namespace gbl::ui
