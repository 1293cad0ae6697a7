// The editor's windows and the tiled layout's rectangles: pure geometry, no ImGui.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <string_view>

namespace gbl::ui {

// Every editor window, in the order they are drawn. Names are ImGui window names, so they
// are also the keys imgui.ini stores the docked layout under.
enum class EditorWindow { Viewport, GBuffer, PixelInspector, Lights, Pipeline, Stats, Log, Lessons };
inline constexpr std::array<std::string_view, 8> kEditorWindowNames{
    "Viewport", "G-buffer", "Pixel inspector", "Lights", "Pipeline", "Stats", "Log", "Lessons"};

inline char const* windowName(EditorWindow w) {
    return kEditorWindowNames[std::size_t(w)].data();
}

struct LayoutState {
    bool resetRequested = false;  // "Reset layout" in the View menu
    bool dockBuilt = false;       // the dock tree exists (from imgui.ini or built this session)
};

struct TileRect {
    glm::vec2 pos{0.0f};
    glm::vec2 size{0.0f};
};

// Fractions of the work area: the side columns keep their widths, the centre gets the rest.
// At 1280x720 the side columns are about 300 px: the narrowest that fits the Lights and Pipeline
// rows in the built-in 13 px font without cutting a label.
inline constexpr float kLeftColumn = 0.24f;
inline constexpr float kRightColumn = 0.26f;
inline constexpr float kViewerStrip = 0.30f;  // share of the centre column below the viewport
// Shares of the column heights: Lights over Pipeline (each about half, so the Pipeline panel
// shows all its rows from 1600x900 on); Pixel inspector over Stats over Log on the right.
inline constexpr float kLightsShare = 0.50f;
inline constexpr float kInspectorShare = 0.46f;
inline constexpr float kStatsShare = 0.34f;
// The Lessons window (its text beside the frame) takes this share of the strip below the
// viewport, on the right of the G-buffer viewers.
inline constexpr float kLessonsShare = 0.42f;

// Where a window sits in the tiled arrangement (no docking): lights over pipeline on the
// left, viewport over the G-buffer strip in the centre, pixel inspector over stats over log on
// the right. The rectangles cover the work area exactly, without overlap.
TileRect tiledRect(EditorWindow window, glm::vec2 workPos, glm::vec2 workSize);

}  // namespace gbl::ui
