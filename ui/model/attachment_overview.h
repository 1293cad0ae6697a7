// The viewport's attachment overview (issue 26): every attachment of the G-buffer layout and the lit
// frame side by side in one grid, each cell labelled; a click on a cell shows that view full size.
// The cells' choice and placement as plain values; no ImGui, no GL.
#pragma once

#include "core/pipeline_settings.h"
#include "model/viewer_state.h"

#include <glm/glm.hpp>

#include <optional>
#include <string_view>
#include <vector>

namespace gbl::ui {

struct OverviewCell {
    DebugView view = DebugView::Final;  // what a click on the cell shows full size
    glm::vec4 image{0.0f};              // the cell's picture in window coordinates: x, y, width, height
};

struct OverviewState {
    bool on = false;                  // the G key or the toolbar's button toggles it
    glm::vec4 buttonRect{0.0f};       // the toolbar's button (x, y, w, h), for the frame log
    std::vector<OverviewCell> cells;  // as last drawn; empty while the overview is off
    // Each cell's range and read-back, auto-fitted as the viewport's tools are (cells of views no
    // viewer covers leave theirs unused). Filled by the loop.
    std::vector<ViewportTools> viewers;
};

// The views of the overview, in reading order: the lit frame, then position, normal, albedo,
// specular and depth of the layout, decoded as the lighting reads them (layouts that rebuild
// position from depth show the rebuilt one; depth linearised). The emissive_ao attachment of the
// layouts that have one stays in "Show": the default scene emits nothing and occludes nothing, so
// its cells would be flat black and white.
std::vector<DebugView> overviewViews();

// The cell's label: the view's name, with what the lit frame is.
std::string_view overviewLabel(DebugView view);

// Splits `area` (x, y, width, height) into the grid of `count` cells whose pictures, kept at the
// frame's aspect (width / height) under a label line of `labelHeight`, come out largest, and
// returns each picture's rectangle, row by row. Pictures are centred in their cells with `gap`
// between cells; none when the area is too small to hold them.
std::vector<glm::vec4> overviewImageRects(int count, glm::vec4 area, float frameAspect, float labelHeight, float gap);

// The cell whose picture holds the point (window coordinates), or -1.
int overviewCellAt(std::vector<OverviewCell> const& cells, glm::vec2 point);

}  // namespace gbl::ui
