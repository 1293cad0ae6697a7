// The few Dear ImGui API differences between Debian's 1.86 and 1.92 (docking), in one place.
#pragma once

#include <imgui.h>

#include <cstdint>

namespace gbl::ui {

// True when this ImGui build has the docking API (docking branch or vcpkg docking-experimental).
#ifdef IMGUI_HAS_DOCK
inline constexpr bool kHasDocking = true;
#else
inline constexpr bool kHasDocking = false;
#endif

// A GL texture name as ImGui wants it: ImTextureID is void* in 1.86 and an integer in 1.92
// (where it converts implicitly to the ImTextureRef that Image() and AddImage() take).
inline ImTextureID toImTexture(unsigned int glTexture) {
    return (ImTextureID)(std::uintptr_t)glTexture;
}

// Window flag that keeps a floating window out of the dock tree (no such thing without docking).
#ifdef IMGUI_HAS_DOCK
inline constexpr ImGuiWindowFlags kNoDockingFlag = ImGuiWindowFlags_NoDocking;
#else
inline constexpr ImGuiWindowFlags kNoDockingFlag = 0;
#endif

// Flags set once at start-up: keyboard navigation everywhere, docking when the build has it.
inline void enableConfigFlags(ImGuiIO& io) {
    io.ConfigFlags |= ImGuiConfigFlags_NavEnableKeyboard;
#ifdef IMGUI_HAS_DOCK
    io.ConfigFlags |= ImGuiConfigFlags_DockingEnable;
#endif
}

// A framed child region: 1.86 takes `bool border`, 1.90+ takes ImGuiChildFlags.
inline bool beginFramedChild(char const* id, ImVec2 size, ImGuiWindowFlags flags = 0) {
#if IMGUI_VERSION_NUM >= 19000
    return ImGui::BeginChild(id, size, ImGuiChildFlags_Borders, flags);
#else
    return ImGui::BeginChild(id, size, true, flags);
#endif
}

// A labelled separator (SeparatorText exists from 1.89.4 on).
inline void separatorText(char const* label) {
#if IMGUI_VERSION_NUM >= 18940
    ImGui::SeparatorText(label);
#else
    ImGui::Spacing();
    ImGui::TextDisabled("%s", label);
    ImGui::Separator();
#endif
}

// Right edge of the content area, taken at the start of a row (GetWindowContentRegionMax is
// obsolete in 1.92).
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

// Key presses that read the same on ImGui 1.86 (keys by GLFW code) and 1.87+ (named keys).
inline bool letterPressed(char upper) {
#if IMGUI_VERSION_NUM >= 18700
    return ImGui::IsKeyPressed(ImGuiKey(int(ImGuiKey_A) + (upper - 'A')));
#else
    return ImGui::IsKeyPressed(int(upper));  // GLFW key codes of letters are their capitals
#endif
}

// An arrow key: dx or dy is -1 or +1 (the other 0); y grows downwards, as on screen.
inline bool arrowPressed(int dx, int dy) {
    ImGuiKey const key = dx < 0   ? ImGuiKey_LeftArrow
                         : dx > 0 ? ImGuiKey_RightArrow
                         : dy < 0 ? ImGuiKey_UpArrow
                                  : ImGuiKey_DownArrow;
#if IMGUI_VERSION_NUM >= 18700
    return ImGui::IsKeyPressed(key);
#else
    return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key));
#endif
}

// Escape went down this frame (1.87 made ImGuiKey values the keys themselves).
inline bool escapePressed() {
#if IMGUI_VERSION_NUM >= 18700
    return ImGui::IsKeyPressed(ImGuiKey_Escape, false);
#else
    return ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
#endif
}

// Marks this frame's press of `button` as the second of a double click. Called after NewFrame,
// which decides double clicks from frame times; the editor decides them from event times
// instead (model/input_events.h), so they work at a few frames per second. 1.86 started
// counting clicks, and from then on IsMouseDoubleClicked reads the count.
inline void markDoubleClick(int button) {
    ImGuiIO& io = ImGui::GetIO();
    io.MouseDoubleClicked[button] = true;
#if IMGUI_VERSION_NUM >= 18600
    io.MouseClickedCount[button] = 2;
    io.MouseClickedLastCount[button] = 2;
#endif
}

}  // namespace gbl::ui
