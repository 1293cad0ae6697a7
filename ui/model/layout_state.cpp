// Rectangles of the tiled layout.
#include "model/layout_state.h"

#include <cmath>

namespace gbl::ui {

TileRect tiledRect(EditorWindow window, glm::vec2 workPos, glm::vec2 workSize) {
    // Whole pixels, so neighbouring windows share edges exactly.
    float const leftW = std::floor(workSize.x * kLeftColumn);
    float const rightW = std::floor(workSize.x * kRightColumn);
    float const centreW = workSize.x - leftW - rightW;
    float const h = workSize.y;
    float const stripH = std::floor(h * kViewerStrip);
    float const leftTopH = std::floor(h * kLightsShare);
    float const rightTopH = std::floor(h * kInspectorShare);
    float const statsH = std::floor(h * kStatsShare);
    float const lessonsW = std::floor(centreW * kLessonsShare);
    glm::vec2 const p = workPos;
    switch (window) {
        case EditorWindow::Lights:
            return {p, {leftW, leftTopH}};
        case EditorWindow::Pipeline:
            return {p + glm::vec2(0, leftTopH), {leftW, h - leftTopH}};
        case EditorWindow::Viewport:
            return {p + glm::vec2(leftW, 0), {centreW, h - stripH}};
        case EditorWindow::GBuffer:
            return {p + glm::vec2(leftW, h - stripH), {centreW - lessonsW, stripH}};
        case EditorWindow::Lessons:
            return {p + glm::vec2(leftW + centreW - lessonsW, h - stripH), {lessonsW, stripH}};
        case EditorWindow::PixelInspector:
            return {p + glm::vec2(leftW + centreW, 0), {rightW, rightTopH}};
        case EditorWindow::Stats:
            return {p + glm::vec2(leftW + centreW, rightTopH), {rightW, statsH}};
        case EditorWindow::Log:
            return {p + glm::vec2(leftW + centreW, rightTopH + statsH), {rightW, h - rightTopH - statsH}};
    }
    return {};
}

}  // namespace gbl::ui
