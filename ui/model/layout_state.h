// The editor's windows and the default dock layout's shares and rectangles: pure geometry, no ImGui.
#pragma once

#include "model/ui_scale.h"

#include <glm/glm.hpp>

#include <array>
#include <string_view>
#include <utility>
#include <vector>

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

// Where a window is docked, as last drawn (the frame log's "docks" and "windowTabs").
struct WindowDock {
    unsigned dockId = 0;  // the dock node it is in; 0 when it floats (or is not drawn)
    glm::vec4 tab{0.0f};  // its tab (docked) or title bar (floating): x, y, width, height in window coordinates
};

// The default layout's boundaries as shares: the columns' widths and the strip's height of the
// work area, the Lights row and the right column's three row boundaries (from the top) of the band
// above the strip.
struct LayoutSplits {
    float left = 0.0f;
    float right = 0.0f;
    float strip = 0.0f;
    float lights = 0.0f;
    std::array<float, 3> rightRows{};  // below Pixel inspector, Lessons, Stats
};

// A docked window grown to show what it holds (panels/layout.h, fitWindowHeight): whether it wanted
// the height last frame, the frames left to try, what it showed (a key that asks for a new fit when
// it changes), the work area and scale it last fitted, and the dock nodes' heights before the
// first grow (node ID, height), put back when it no longer wants them.
struct DockHeightFit {
    bool wasOpen = false;
    int triesLeft = 0;
    long key = 0;
    glm::vec2 workSize{0.0f};
    float scale = 0.0f;
    std::vector<std::pair<unsigned, float>> saved;
};

// Which default dock layout fits the work area at a UI scale (chooseDockLayout): two side columns
// beside the viewport (Lights over Pipeline left; Pixel inspector, Lessons, Stats, Log right), or at
// a large scale one side column of two tabbed nodes (Lights, Pipeline and Pixel inspector over
// Lessons, Stats and Log), since two columns wide enough for their text would leave the viewport
// less than half the width.
enum class DockLayoutKind { TwoColumns, OneColumn };
char const* dockLayoutName(DockLayoutKind kind);  // "two columns", "one column" (the frame log)

// The G-buffer strip's height fitted to its images (panels/layout.h, fitStripHeight): the frames
// left to try after the layout was built, each taking the strip's spare height (or what its images
// lack) from the band above it.
struct StripFit {
    int triesLeft = 0;
    glm::vec2 workSize{0.0f};  // the work area it last fitted
};

struct LayoutState {
    bool resetRequested = false;  // "Reset layout" in the View menu
    bool dockBuilt = false;       // the dock tree exists (from imgui.ini or built this session)
    // The kind and UI scale (uiScaleFactor) the dock tree was built for: a scale that differs from
    // this one (View > UI scale, or a layout file written at another scale) or a window whose size
    // asks for the other kind builds the default layout again. builtScale 0: a tree from a layout
    // file that did not say (kept as it is until the scale changes).
    DockLayoutKind builtKind = DockLayoutKind::TwoColumns;
    float builtScale = 0.0f;
    StripFit stripFit;
    UiScaleState scale;  // the View menu's UI scale, kept in imgui.ini with the layout
    std::array<WindowDock, kEditorWindowNames.size()> docks{};  // EditorWindow order, as last drawn
    glm::vec4 fileMenuRect{0.0f};                               // the menu bar's "File", for the frame log
    glm::vec4 viewMenuRect{0.0f};                               // its "View"
    glm::vec4 resetLayoutRect{0.0f};                            // View > Reset layout while the menu is open
    glm::vec4 uiScaleMenuRect{0.0f};                            // View > UI scale while the menu is open
    std::vector<glm::vec4> uiScaleItemRects;                    // its choices while that submenu is open
    DockHeightFit lessonFit;                                    // the Lessons window while a lesson is open
    DockHeightFit lightsFit;  // the Lights window while a light is selected (its attenuation plot)
    // The presentation layout (panels/panel_presentation.h; the P key, View > Presentation): while
    // on, the dock tree is kept but not drawn. Its caption and the lesson's place beside the image as
    // last drawn (0 while off), and View > Presentation's row while the menu is open.
    bool presentation = false;
    glm::vec4 presentationCaption{0.0f};
    glm::vec4 presentationLesson{0.0f};
    glm::vec4 presentationItemRect{0.0f};
};

// Fractions of the work area. The G-buffer strip spans the whole width below the others, so
// its five viewers get a fifth of the window each (about 250 px at 1280x720: every attachment
// readable at once, as Unreal's buffer overview); above it the side columns keep their widths
// and the viewport gets the rest. At 1280x720 the side columns are about 300 px: the narrowest
// that fits the Lights and Pipeline rows without cutting a label.
inline constexpr float kLeftColumn = 0.235f;
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

// Where the default dock layout puts each window (layout.cpp's DockBuilder splits by the same
// shares): the G-buffer strip along the bottom; above it lights over pipeline on the left, the
// viewport in the centre, pixel inspector over lessons over stats over log on the right. The
// rectangles cover the work area exactly, without overlap; every one keeps a least size
// (kTileLeastPx) as far as the work area allows.
TileRect defaultWindowRect(EditorWindow window, glm::vec2 workPos, glm::vec2 workSize, float uiScale = 1.0f);

// The boundaries the fractions above (and the least sizes at this scale) give.
LayoutSplits defaultSplits(glm::vec2 workSize, float uiScale);

// The one-column layout (DockLayoutKind::OneColumn). The side column's least width at scale 1: the
// widest of its windows' rows (a lesson's buttons, the Stats and Pixel inspector tables: about 256 px
// at scale 1) with a scrollbar beside them; it takes at least kOneColumnShare of the width, and never more than leaves
// the viewport kViewportHalf of it. The column's upper node (Lights, Pipeline, Pixel inspector)
// takes kOneColumnTopShare of the band above the strip; Lessons, Stats and Log share the rest.
inline constexpr float kOneColumnLeastPx = 284.0f;
inline constexpr float kOneColumnShare = 0.30f;
inline constexpr float kOneColumnTopShare = 0.50f;
inline constexpr float kViewportHalf = 0.50f;

// Two columns while both, at their least widths at this scale, leave the viewport at least
// kViewportHalf of the width (at scale 1 or below always, as before there was a scale); otherwise
// one column.
DockLayoutKind chooseDockLayout(glm::vec2 workSize, float uiScale);

// The one side column's share of the work area's width at this size and scale.
float oneColumnShare(glm::vec2 workSize, float uiScale);

// The smallest width or height a window keeps in the default layout, at scale 1.
inline constexpr float kTileLeastPx = 48.0f;

}  // namespace gbl::ui
