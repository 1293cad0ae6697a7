// Frame window (issue 24): the current frame's passes as boxes with their resources as pins and
// arrows from the pass that writes a resource to the passes that read it; a pin shows its resource
// in the viewport, a pass shows its declared state and can stop the frame after it.
#pragma once

#include "core/frame_types.h"
#include "core/pipeline_settings.h"
#include "model/frame_diagram.h"

namespace gbl::ui {

inline constexpr char const* kFrameWindowName = "Frame";

// state.passes: the frame's declared passes (drawn entirely from them); last: its statistics
// (pass times, the pass it stopped after). A pin with a view sets settings.view.
void drawFramePanel(FramePanelState& state, PipelineSettings& settings, FrameStats const& last);

}  // namespace gbl::ui
