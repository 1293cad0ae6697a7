// Help > Shortcuts: the editor's shortcut table (model/input_events.h) as a window.
#pragma once

namespace gbl::ui {

// Draws the window while `open`; its close button clears `open`.
void drawShortcutsWindow(bool& open);

}  // namespace gbl::ui
