// Stats window: frame times, pass times and the editor's own cost.
#pragma once

#include "model/stats_state.h"
#include "gl/caps.h"

namespace gbl::ui {

void drawStatsPanel(StatsState const& stats, GlCaps const& caps, int lightCount);

}  // namespace gbl::ui
