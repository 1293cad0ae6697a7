// Stats window: frame times, pass times and the editor's own cost.
#pragma once

#include "gl/caps.h"
#include "model/render_inputs.h"
#include "model/stats_state.h"

#include <string>

namespace gbl::ui {

// render: the loop's render-on-change record, shown as "re-rendered"/"reused" with a checkbox for
// continuous rendering; null hides that line.
void drawStatsPanel(StatsState const& stats, GlCaps const& caps, int lightCount, RenderOnChange* render = nullptr,
                    std::string const& renderReason = {});

}  // namespace gbl::ui
