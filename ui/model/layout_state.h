// The editor's windows and the tiled layout's rectangles: pure geometry, no ImGui.
#pragma once

#include "model/ui_scale.h"

#include <glm/glm.hpp>

#include <array>
#include <optional>
#include <string>
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

struct TileRect {
    glm::vec2 pos{0.0f};
    glm::vec2 size{0.0f};
};

// The tiled layout's boundaries (Debian's ImGui 1.86 has no docking, so the editor draws a handle
// on each boundary and the user drags it): the columns' widths and the strip's height as shares of
// the work area, the Lights row and the right column's three row boundaries (from the top) as
// shares of the band above the strip.
enum class Split { LeftColumn, RightColumn, Strip, LightsRow, InspectorRow, LessonsRow, StatsRow };
inline constexpr std::size_t kSplitCount = 7;
struct LayoutSplits {
    float left = 0.0f;
    float right = 0.0f;
    float strip = 0.0f;
    float lights = 0.0f;
    std::array<float, 3> rightRows{};  // below Pixel inspector, Lessons, Stats
};

struct LayoutState {
    bool resetRequested = false;  // "Reset layout" in the View menu
    bool dockBuilt = false;       // the dock tree exists (from imgui.ini or built this session)
    UiScaleState scale;           // the View menu's UI scale, kept in imgui.ini with the layout
    // Tiled builds: the boundaries as the user dragged them (none = the defaults for the size and
    // scale), kept in imgui.ini; the boundary being dragged (-1 = none).
    std::optional<LayoutSplits> splits;
    int draggingSplit = -1;
    std::array<TileRect, kSplitCount> handles{};  // the handles as last drawn (Split order; the frame log's)
    glm::vec4 fileMenuRect{0.0f};                 // the menu bar's "File", for the frame log
};

// Fractions of the work area. The G-buffer strip spans the whole width below the others, so
// its five viewers get a fifth of the window each (about 250 px at 1280x720: every attachment
// readable at once, as Unreal's buffer overview); above it the side columns keep their widths
// and the viewport gets the rest. At 1280x720 the side columns are about 300 px: the narrowest
// that fits the Lights and Pipeline rows without cutting a label.
inline constexpr float kLeftColumn = 0.24f;
inline constexpr float kRightColumn = 0.26f;
// Share of the height below the others: a viewer's one-line toolbar over an image of the
// frame's aspect at a fifth of the width (the frame is about 1.6:1).
inline constexpr float kViewerStrip = 0.29f;
// Shares of the band above the strip: Lights over Pipeline on the left; Pixel inspector over
// Lessons over Stats over Log on the right.
inline constexpr float kLightsShare = 0.50f;
inline constexpr float kInspectorShare = 0.28f;
// A step's text and equation, and a prediction's question and choices, without scrolling (about
// 215 px at 1280x720; a three-choice prediction's Check button still needs a scroll); the Stats
// window keeps its two lines and the Frame diagram button in view (about 75 px) and the Log what
// is left (about 70 px: its Clear button and the newest lines). Every boundary can be dragged.
inline constexpr float kLessonsShare = 0.43f;
inline constexpr float kStatsShare = 0.15f;

// The narrowest side columns and strip at UI scale 1, in pixels (what the fractions give at
// 1280x720). At a larger scale the text grows, so these grow with it and the columns take a
// larger share of the window; the viewport keeps at least kViewportLeast of the width.
inline constexpr float kLeftColumnLeastPx = 300.0f;
inline constexpr float kRightColumnLeastPx = 320.0f;
inline constexpr float kViewerStripLeastPx = 208.0f;
inline constexpr float kViewportLeast = 0.40f;

// The shares of the work area the side columns and the strip take at this size and UI scale:
// kLeftColumn, kRightColumn and kViewerStrip, or more where those are narrower than the least
// widths above times the scale (at scale 1 the fractions, whatever the size).
struct LayoutShares {
    float left = kLeftColumn;
    float right = kRightColumn;
    float strip = kViewerStrip;
};
LayoutShares layoutShares(glm::vec2 workSize, float uiScale);

// Where a window sits in the tiled arrangement (no docking): the G-buffer strip along the
// bottom; above it lights over pipeline on the left, the viewport in the centre, pixel
// inspector over lessons over stats over log on the right. The rectangles cover the work area
// exactly, without overlap.
// `splits` replaces the default boundaries; every tile keeps a least size (kTileLeastPx) as far as
// the work area allows.
TileRect tiledRect(EditorWindow window, glm::vec2 workPos, glm::vec2 workSize, float uiScale = 1.0f,
                   std::optional<LayoutSplits> const& splits = std::nullopt);

// The boundaries the fractions above (and the least sizes at this scale) give.
LayoutSplits defaultSplits(glm::vec2 workSize, float uiScale);

// The smallest width or height a tile keeps while a boundary is dragged, at scale 1.
inline constexpr float kTileLeastPx = 48.0f;

// Each boundary's handle: a band kSplitHandlePx wide centred on it, in window coordinates
// (Split order).
inline constexpr float kSplitHandlePx = 6.0f;
std::array<TileRect, kSplitCount> splitHandles(glm::vec2 workPos, glm::vec2 workSize, float uiScale,
                                               std::optional<LayoutSplits> const& splits);

// The splits with boundary `split` moved to the mouse (window coordinates), held so that every
// tile keeps its least size.
LayoutSplits dragSplit(std::optional<LayoutSplits> const& splits, Split split, glm::vec2 mouse, glm::vec2 workPos,
                       glm::vec2 workSize, float uiScale);

// The splits' line in the layout file ("Splits=0.24,0.26,...", seven shares in Split order) and
// its reading: seven numbers in (0, 1), the columns leaving room for the viewport and the right
// column's rows in order; otherwise nullopt and one sentence naming `what`.
inline constexpr std::string_view kSplitsKey = "Splits";
std::string splitsLine(LayoutSplits const& splits);
std::optional<LayoutSplits> parseSplits(std::string_view text, std::string_view what, std::string* error = nullptr);

}  // namespace gbl::ui
