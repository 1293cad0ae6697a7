// Log window.
#pragma once

#include "model/log_state.h"

namespace gbl::ui {

void drawLogPanel(LogState& log);

}  // namespace gbl::ui
