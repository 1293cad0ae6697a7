// State of the G-buffer viewers (one per attachment): channels, range, zoom and pan, as plain values.
#pragma once

#include "core/frame_types.h"
#include "core/view_params.h"
#include "model/image_stats.h"

#include <glm/glm.hpp>

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace gbl::ui {

// The five G-buffer viewers, then the lit HDR frame (Attachment::Lighting), which only the
// viewport's tools show (it has no viewer in the G-buffer window, so kViewerNames stops at depth).
enum class ViewerKind { Position, Normal, Albedo, Specular, Depth, Lighting };
inline constexpr std::array<std::string_view, 5> kViewerNames{"position", "normal", "albedo", "specular", "depth"};
// kViewerNames' name of a G-buffer viewer's kind, "lighting" for the lit frame.
inline std::string_view viewerKindName(ViewerKind kind) {
    return kind == ViewerKind::Lighting ? std::string_view("lighting") : kViewerNames[std::size_t(kind)];
}

struct ViewerState {
    ViewerKind kind = ViewerKind::Position;
    unsigned channelMask = 0x7;  // bit 0 = R ... bit 3 = A
    float rangeMin = 0.0f;
    float rangeMax = 1.0f;
    bool autoFit = false;       // refit the range to the data about once a second
    bool fitRequested = false;  // the Fit button; the loop reads the attachment and clears it
    long lastFitFrame = -1;     // frame of the last fit that found data; -1 = never fitted
    NormalDisplay normalDisplay = NormalDisplay::Biased;
    bool linearDepth = true;       // depth viewer: eye distance instead of window depth
    bool cameraClipPlanes = true;  // linear depth with the camera's near/far, else the fields below
    float nearPlane = 0.1f;
    float farPlane = 100.0f;
    float zoom = 1.0f;        // 1 = whole image fits the cell
    glm::vec2 center{0.5f};   // image point (0..1, top-left origin) at the cell centre
    glm::ivec2 imageSize{0};  // texel size of the image last shown

    // --- viewer tools (issue 15); colormap, overlays, histogram and stencil are saved in sessions
    bool showHistogram = false;
    // Depth viewer: show the stencil bits (0..255, read back on the CPU) instead of the depth.
    // The range of the view not shown waits in otherRange, so switching keeps both.
    bool showStencil = false;
    glm::vec2 otherRange{0.0f, 255.0f};
    Colormap colormap = Colormap::Grey;         // when one channel is shown
    unsigned overlays = 0;                      // kOverlay* bits (core/view_params.h)
    std::optional<glm::ivec2> picked;           // magnifier centre: right-click, arrow keys, Ctrl+G
    std::optional<PixelRect> region;            // Shift+drag; statistics and "Fit to region" use it
    std::optional<glm::ivec2> regionDragStart;  // texel where the Shift+drag began
    // Height of the region rows above the image when no drag was on; a drag keeps the rows this tall
    // so the image below them does not move under the mouse (UI layout, not saved).
    float regionRowsHeight = 0.0f;
    int histogramDrag = -1;               // 0: dragging the black point, 1: the white point
    bool percentileFitRequested = false;  // "Fit 1-99 %": serviced like fitRequested
    bool regionFitRequested = false;      // "Fit to region": min/max inside the region
    bool pinRequested = false;            // "Pin": the loop stores the current values as the pinned image
    bool showDiff = false;                // show |current - pinned| as a heat map instead of the view
    DiffMode diffMode = DiffMode::Absolute;
    float diffThreshold = 0.0f;  // pixels above it are counted ("over threshold")
    // msaa (issue 47): the sample shown, -1 for all (the resolved attachment); a sample is read
    // back from the multisampled G-buffer and coloured on the CPU. The depth viewer shows all.
    int sample = -1;
};

// What the statistics of a ViewerData were computed for; a change recomputes them.
struct StatsInputs {
    unsigned mask = 0;
    float black = 0.0f, white = 1.0f;
    std::optional<PixelRect> region;
    float diffThreshold = 0.0f;
    DiffMode diffMode = DiffMode::Absolute;
    bool operator==(StatsInputs const&) const = default;
};

// What the viewer tools know about one viewer's image, filled by the editor loop from a read-back
// (ui/viewer_tools_service.cpp). Lives outside ViewerState so sessions never copy images.
struct ViewerData {
    FloatImage values;  // the viewer's values in data units (see viewerValues)
    long frame = -1;    // editor frame of the read-back; -1 = none yet
    unsigned key = 0;   // what the values were computed for (kind, depth mode); a change rereads
    ImageStats stats;   // whole image
    ImageStats regionStats;
    Histogram histogram;  // over the histogram range below
    float histLo = 0.0f, histHi = 1.0f;
    ClipCounts clip;  // against the viewer's black/white points
    std::optional<FloatImage> pinned;
    long pinnedFrame = -1;
    DiffStats diff;
    std::optional<StatsInputs> computedFor;
    // What the last auto-fit was for: the values key (viewerValuesKey) and the clip planes that
    // linearised depth. Either changing (raw to linear depth, a lesson's far plane) makes the
    // range meaningless, so auto-fit refits at once instead of waiting for its next turn.
    std::optional<std::pair<unsigned, glm::vec2>> autoFitFor;
};

struct GBufferPanelState {
    std::array<ViewerState, 5> viewers = defaultViewers();
    // Redrawing five full-size views every frame costs as much as a lighting pass on a software
    // GL, so by default one viewer is redrawn per frame in turn (and any viewer at once when its
    // settings change). On a GPU at 60 Hz that is still 12 refreshes a second per viewer.
    bool refreshEveryFrame = false;
    int nextRefresh = 0;
    bool visible = true;                      // the window was drawn last frame; hidden viewers are not redrawn
    std::optional<glm::ivec2> hoverPixel;     // texel under the mouse in any viewer, top-left origin
    std::optional<DebugView> showInViewport;  // a viewer was clicked this frame
    bool syncViews = false;                   // zoom/pan of one viewer is applied to all (same texel under the cursor)
    int activeViewer = 0;                     // the viewer last clicked or hovered: the magnifier and Ctrl+G act on it
    bool showMagnifier = false;
    bool goToOpen = false;  // Ctrl+G was pressed: the go-to-pixel popup opens
    glm::ivec2 goToInput{0};
    std::array<ViewerData, 5> data{};  // read-backs for the tools, filled by the loop
    // Each viewer's image at zoom 1 in window coordinates (x, y, width, height) as last drawn, for
    // the frame log (UI layout, not saved).
    std::array<glm::vec4, 5> imageRects{};
    // The first viewer's image area (its cell below the toolbar) as last drawn: the dock layout
    // fits the strip's height to it (panels/layout.h, fitStripHeight).
    glm::vec2 imageArea{0.0f};
    // Set by the loop each frame, per viewer: why the lighting mode stores nothing that viewer shows
    // (the forward modes: no G-buffer; prepass: no albedo), which it says instead of showing a blank
    // or stale image; empty when it stores it (noGBufferNote).
    std::array<std::string, 5> noGBuffer{};
    // ... and where a viewer's values come from when not from the layout's G-buffer (prepass's thin
    // one), a caption over its image; empty otherwise (thinGBufferSource).
    std::array<std::string, 5> source{};
    // Set by the loop each frame: samples per pixel of the frame shown (0: no msaa), for the
    // viewers' and the magnifier's sample selectors.
    int msaaSamples = 0;
    // Each viewer's sample selector on its toolbar as last drawn (x, y, w, h; 0 when not drawn), for
    // the frame log (UI layout, not saved).
    std::array<glm::vec4, 5> sampleRects{};

    static std::array<ViewerState, 5> defaultViewers();
};

// The viewer tools in the viewport, while it shows a G-buffer attachment or the lit HDR frame (the
// lighting view, in data units before the tonemap): one ViewerState whose
// kind follows the viewport's view, and its data. Drawn into its own view target by the loop.
// GBufferPanelState::activeViewer of the viewport's tools (the magnifier shows their texel).
inline constexpr int kViewportViewer = 5;

struct ViewportTools {
    // The viewport's "Tools" toggle. On from the start: an attachment picked in "Show" opens
    // auto-ranged (depth linearised, positions over the scene), not blank white or black.
    bool open = true;
    ViewerState viewer = defaultViewer();
    ViewerData data;
    // Magnifier and region input of the viewport image (the G-buffer viewers keep theirs).
    std::optional<glm::ivec2> hoverTexel;
    bool pickedThisFrame = false;  // Shift+right-click picked a texel: the magnifier switches to it

    static ViewerState defaultViewer();
};

// The viewer kind a viewport view shows, or nothing (final, heat map, tile lights).
std::optional<ViewerKind> viewerKindOfView(DebugView view);
// Makes the viewport's viewer follow the view: kind and linear depth. False when the view is
// neither a G-buffer attachment nor the lit frame (the tools then stay hidden).
bool followViewportView(ViewportTools& tools, DebugView view);
// What the G-buffer viewer `kind` says in `mode` instead of an image (GBufferPanelState::noGBuffer):
// the forward modes write no G-buffer; prepass's thin one (normal, exponent, depth) holds no albedo.
// Empty where the viewer has values to show.
std::string noGBufferNote(LightingMode mode, ViewerKind kind);
// Where viewer `kind`'s values come from in `mode` when not from the layout's G-buffer: prepass's
// thin G-buffer (docs/deferred_lighting.md). Empty otherwise.
std::string thinGBufferSource(LightingMode mode, ViewerKind kind);
// Switches the depth viewer between depth and stencil, swapping in the other view's range.
void setShowStencil(ViewerState& viewer, bool on);

DebugView viewerDebugView(ViewerState const& viewer);
// The view-pass parameters a viewer asks for (the loop passes them to Renderer::drawView).
ViewParams viewerParams(ViewerState const& viewer);

// The attachment a viewer shows and how its values are taken from it, for the tools.
Attachment viewerAttachment(ViewerKind kind);
// ... with the depth viewer's stencil switch: Attachment::Stencil while it shows the stencil.
Attachment viewerAttachment(ViewerState const& viewer);
// The viewer's values as 4 channels in data units: position/normal/albedo as stored (alpha = drawn),
// specular in channel 3, depth as (shown depth: linear when the viewer linearises, raw window depth,
// 0, 1 where geometry was drawn), the stencil (depth viewer with showStencil) as (value, value,
// 0, 1) with every pixel counted. Statistics use viewerStatsMask and RangeSkip::ZeroAlpha
// (albedo and specular: RangeSkip::None).
FloatImage viewerValues(ViewerState const& viewer, FloatImage const& attachment, float nearPlane, float farPlane);
unsigned viewerStatsMask(ViewerState const& viewer);
RangeSkip viewerSkip(ViewerKind kind);
// Whether the viewer's range remap applies (normals are shown as directions instead).
inline bool viewerRemaps(ViewerKind kind) {
    return kind != ViewerKind::Normal;
}

}  // namespace gbl::ui
