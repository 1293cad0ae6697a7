// Rectangles of the tiled layout.
#include "model/layout_state.h"

#include <cmath>

namespace gbl::ui {

TileRect tiledRect(EditorWindow window, glm::vec2 workPos, glm::vec2 workSize) {
    // Whole pixels, so neighbouring windows share edges exactly.
    float const leftW = std::floor(workSize.x * kLeftColumn);
    float const rightW = std::floor(workSize.x * kRightColumn);
    float const centreW = workSize.x - leftW - rightW;
    float const stripH = std::floor(workSize.y * kViewerStrip);
    float const h = workSize.y - stripH;  // the band above the strip
    float const leftTopH = std::floor(h * kLightsShare);
    float const inspectorH = std::floor(h * kInspectorShare);
    float const lessonsH = std::floor(h * kLessonsShare);
    float const statsH = std::floor(h * kStatsShare);
    glm::vec2 const p = workPos;
    float const rightX = leftW + centreW;
    switch (window) {
        case EditorWindow::Lights:
            return {p, {leftW, leftTopH}};
        case EditorWindow::Pipeline:
            return {p + glm::vec2(0, leftTopH), {leftW, h - leftTopH}};
        case EditorWindow::Viewport:
            return {p + glm::vec2(leftW, 0), {centreW, h}};
        case EditorWindow::GBuffer:
            return {p + glm::vec2(0, h), {workSize.x, stripH}};
        case EditorWindow::PixelInspector:
            return {p + glm::vec2(rightX, 0), {rightW, inspectorH}};
        case EditorWindow::Lessons:
            return {p + glm::vec2(rightX, inspectorH), {rightW, lessonsH}};
        case EditorWindow::Stats:
            return {p + glm::vec2(rightX, inspectorH + lessonsH), {rightW, statsH}};
        case EditorWindow::Log:
            return {p + glm::vec2(rightX, inspectorH + lessonsH + statsH),
                    {rightW, h - inspectorH - lessonsH - statsH}};
    }
    return {};
}

}  // namespace gbl::ui
