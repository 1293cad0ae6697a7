// The "discard unsaved edits?" window in front of Quit, New and Open.
#pragma once

#include "model/discard_guard.h"

namespace gbl::ui {

// While guard.asking: a modal with Discard and Cancel. Discard moves the action to
// guard.confirmed; Cancel or Escape forgets it.
void drawDiscardConfirmation(DiscardGuard& guard);

}  // namespace gbl::ui
