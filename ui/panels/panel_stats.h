// Stats window: frame times, pass times and the editor's own cost.
#pragma once

#include "model/frame_diagram.h"
#include "model/render_inputs.h"
#include "model/stats_state.h"

#include <string>

namespace gbl::ui {

// maxStorageBlockBytes: the context's storage-block limit, which sizes the tiles' light lists (GlCaps).
// noFragmentCounts: why the context counts no fragment invocations (GlCaps's
// pipelineStatisticsUnavailableReason(); the panels know no GL). render: the loop's render-on-change record, shown as
// "re-rendered"/"reused" with a checkbox for continuous rendering; null hides that line. frame: the Frame window,
// opened by a button beside the pass times; null hides the button.
void drawStatsPanel(StatsState const& stats, std::string const& noFragmentCounts, int lightCount,
                    long long maxStorageBlockBytes, RenderOnChange* render = nullptr,
                    std::string const& renderReason = {}, FramePanelState* frame = nullptr);

}  // namespace gbl::ui
