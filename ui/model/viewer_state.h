// State of the G-buffer viewers (one per attachment): channels, range, zoom and pan, as plain values.
#pragma once

#include "core/view_params.h"

#include <glm/glm.hpp>

#include <array>
#include <optional>
#include <string_view>

namespace gbl::ui {

enum class ViewerKind { Position, Normal, Albedo, Specular, Depth };
inline constexpr std::array<std::string_view, 5> kViewerNames{"position", "normal", "albedo", "specular", "depth"};

struct ViewerState {
    ViewerKind kind = ViewerKind::Position;
    unsigned channelMask = 0x7;  // bit 0 = R ... bit 3 = A
    float rangeMin = 0.0f;
    float rangeMax = 1.0f;
    bool autoFit = false;        // refit the range to the data about once a second
    bool fitRequested = false;   // the Fit button; the loop reads the attachment and clears it
    long lastFitFrame = -1;      // frame of the last fit that found data; -1 = never fitted
    NormalDisplay normalDisplay = NormalDisplay::Biased;
    bool linearDepth = true;     // depth viewer: eye distance instead of window depth
    bool cameraClipPlanes = true;  // linear depth with the camera's near/far, else the fields below
    float nearPlane = 0.1f;
    float farPlane = 100.0f;
    float zoom = 1.0f;           // 1 = whole image fits the cell
    glm::vec2 center{0.5f};      // image point (0..1, top-left origin) at the cell centre
    glm::ivec2 imageSize{0};     // texel size of the image last shown
};

struct GBufferPanelState {
    std::array<ViewerState, 5> viewers = defaultViewers();
    // Redrawing five full-size views every frame costs as much as a lighting pass on a software
    // GL, so by default one viewer is redrawn per frame in turn (and any viewer at once when its
    // settings change). On a GPU at 60 Hz that is still 12 refreshes a second per viewer.
    bool refreshEveryFrame = false;
    int nextRefresh = 0;
    bool visible = true;  // the window was drawn last frame; hidden viewers are not redrawn
    std::optional<glm::ivec2> hoverPixel;  // texel under the mouse in any viewer, top-left origin
    std::optional<DebugView> showInViewport;  // a viewer was clicked this frame

    static std::array<ViewerState, 5> defaultViewers();
};

DebugView viewerDebugView(ViewerState const& viewer);
// The view-pass parameters a viewer asks for (the loop passes them to Renderer::drawView).
ViewParams viewerParams(ViewerState const& viewer);

}  // namespace gbl::ui
