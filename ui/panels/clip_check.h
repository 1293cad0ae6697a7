// Finds UI content that ImGui cut off this frame where ImGui can tell: a window whose content is
// wider than its visible area with no horizontal scrollbar, and a table column whose text is
// wider than the column. For --log-frames and the layout test.
#pragma once

#include <string>
#include <vector>

namespace gbl::ui {

// One sentence per cut-off item ("Pipeline: content 312 px wide in 281 px, no scrollbar").
// Call after the frame's windows have ended (after ImGui::Render or EndFrame).
std::vector<std::string> clippedItems();

}  // namespace gbl::ui
