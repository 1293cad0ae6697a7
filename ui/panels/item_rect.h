// The last ImGui item's rectangle as the frame log writes rectangles (x, y, width, height in
// window coordinates), for the tests that click what the editor drew.
#pragma once

#include <imgui.h>
#include <glm/glm.hpp>

namespace gbl::ui {

inline glm::vec4 lastItemRect() {
    ImVec2 const a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    return {a.x, a.y, b.x - a.x, b.y - a.y};
}

}  // namespace gbl::ui
