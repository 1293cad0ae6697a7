// The attachment overview's cells and their grid.
#include "model/attachment_overview.h"

#include <algorithm>
#include <cmath>

namespace gbl::ui {

std::vector<DebugView> overviewViews() {
    // Every layout stores (or rebuilds) these; the position cell of a layout without a position
    // attachment shows the rebuilt one, as its full-size view does.
    return {DebugView::Final,  DebugView::Position, DebugView::Normal,
            DebugView::Albedo, DebugView::Specular, DebugView::DepthLinear};
}

std::string_view overviewLabel(DebugView view) {
    if (view == DebugView::Final) return "final (lit, tonemapped)";
    if (view == DebugView::DepthLinear) return "depth (linear)";
    return kDebugViewNames[std::size_t(view)];
}

std::vector<glm::vec4> overviewImageRects(int count, glm::vec4 area, float frameAspect, float labelHeight, float gap) {
    std::vector<glm::vec4> out;
    if (count <= 0 || !(frameAspect > 0.0f)) return out;
    // The column count whose pictures are largest; ties go to fewer columns (larger rows).
    int bestColumns = 0;
    float bestWidth = 0.0f;
    for (int columns = 1; columns <= count; ++columns) {
        int const rows = (count + columns - 1) / columns;
        float const cellW = (area.z - gap * float(columns - 1)) / float(columns);
        float const cellH = (area.w - gap * float(rows - 1)) / float(rows) - labelHeight;
        float const w = std::min(cellW, cellH * frameAspect);
        if (w > bestWidth + 0.5f) {
            bestWidth = w;
            bestColumns = columns;
        }
    }
    if (bestColumns == 0 || bestWidth < 8.0f) return out;
    int const columns = bestColumns, rows = (count + columns - 1) / columns;
    float const cellW = (area.z - gap * float(columns - 1)) / float(columns);
    float const w = std::floor(bestWidth), h = std::floor(bestWidth / frameAspect);
    // The block of cells centred in the area, each picture centred in its cell under its label.
    float const blockH = float(rows) * (labelHeight + h) + gap * float(rows - 1);
    float const top = area.y + std::floor(std::max(0.0f, area.w - blockH) * 0.5f);
    for (int i = 0; i < count; ++i) {
        int const col = i % columns, row = i / columns;
        float const x = area.x + float(col) * (cellW + gap) + std::floor((cellW - w) * 0.5f);
        float const y = top + float(row) * (labelHeight + h + gap) + labelHeight;
        out.emplace_back(x, y, w, h);
    }
    return out;
}

int overviewCellAt(std::vector<OverviewCell> const& cells, glm::vec2 p) {
    for (std::size_t i = 0; i < cells.size(); ++i) {
        glm::vec4 const r = cells[i].image;
        if (p.x >= r.x && p.x < r.x + r.z && p.y >= r.y && p.y < r.y + r.w) return int(i);
    }
    return -1;
}

}  // namespace gbl::ui
