// Small Dear ImGui helpers the panels share: GL textures as ImGui textures, framed children,
// rows that wrap, key presses and the editor's own double clicks.
#pragma once

#include <imgui.h>

#include <cstdint>

namespace gbl::ui {

// A GL texture name as ImGui wants it: ImTextureID is an integer that converts implicitly to the
// ImTextureRef that Image() and AddImage() take (the OpenGL3 backend binds it as a GL name).
inline ImTextureID toImTexture(unsigned int glTexture) {
    return ImTextureID(std::uintptr_t(glTexture));
}

// Flags set once at start-up: keyboard navigation and docking. Multi-viewport stays off: the
// browser has no second window, and the editor's windows stay inside its own.
inline void enableConfigFlags(ImGuiIO& io) {
    io.ConfigFlags |= ImGuiConfigFlags_NavEnableKeyboard | ImGuiConfigFlags_DockingEnable;
}

// A framed child region.
inline bool beginFramedChild(char const* id, ImVec2 size, ImGuiWindowFlags flags = 0) {
    return ImGui::BeginChild(id, size, ImGuiChildFlags_Borders, flags);
}

// A labelled separator.
inline void separatorText(char const* label) {
    ImGui::SeparatorText(label);
}

// Right edge of the content area, taken at the start of a row.
inline float rowRightEdge() {
    return ImGui::GetCursorScreenPos().x + ImGui::GetContentRegionAvail().x;
}

// Puts the next item on the current line when `itemWidth` still fits before `rightEdge`, else
// on a new line: radio rows wrap in narrow side columns instead of running off the window.
inline void sameLineIfFits(float itemWidth, bool firstInRow, float rightEdge) {
    if (firstInRow) return;
    float const spacing = ImGui::GetStyle().ItemSpacing.x;
    if (ImGui::GetItemRectMax().x + spacing + itemWidth <= rightEdge) ImGui::SameLine();
}

// Width of a radio button or checkbox with this label.
inline float checkItemWidth(char const* label) {
    return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label).x;
}

// A letter key went down this frame (`upper` is its capital).
inline bool letterPressed(char upper) {
    return ImGui::IsKeyPressed(ImGuiKey(int(ImGuiKey_A) + (upper - 'A')));
}

// An arrow key: dx or dy is -1 or +1 (the other 0); y grows downwards, as on screen.
inline bool arrowPressed(int dx, int dy) {
    ImGuiKey const key = dx < 0   ? ImGuiKey_LeftArrow
                         : dx > 0 ? ImGuiKey_RightArrow
                         : dy < 0 ? ImGuiKey_UpArrow
                                  : ImGuiKey_DownArrow;
    return ImGui::IsKeyPressed(key);
}

// Escape went down this frame.
inline bool escapePressed() {
    return ImGui::IsKeyPressed(ImGuiKey_Escape, false);
}

// Marks this frame's press of `button` as the second of a double click. Called after NewFrame,
// which decides double clicks from frame times; the editor decides them from event times
// instead (model/input_events.h), so they work at a few frames per second.
inline void markDoubleClick(int button) {
    ImGuiIO& io = ImGui::GetIO();
    io.MouseDoubleClicked[button] = true;
    io.MouseClickedCount[button] = 2;
    io.MouseClickedLastCount[button] = 2;
}

}  // namespace gbl::ui
