// Rectangles of the tiled layout.
#include "model/layout_state.h"

#include <algorithm>
#include <cmath>

namespace gbl::ui {

LayoutShares layoutShares(glm::vec2 workSize, float uiScale) {
    LayoutShares s;
    // At scale 1 (or smaller) the fractions hold at every size, as before there was a scale.
    if (uiScale <= 1.0f || workSize.x <= 0.0f || workSize.y <= 0.0f) return s;
    s.left = std::max(kLeftColumn, scaledPixels(kLeftColumnLeastPx, uiScale) / workSize.x);
    s.right = std::max(kRightColumn, scaledPixels(kRightColumnLeastPx, uiScale) / workSize.x);
    // Both columns give up width in proportion when the viewport would get less than its least.
    float const sides = 1.0f - kViewportLeast;
    if (s.left + s.right > sides) {
        float const f = sides / (s.left + s.right);
        s.left = std::max(kLeftColumn, s.left * f);
        s.right = std::max(kRightColumn, s.right * f);
    }
    s.strip = std::clamp(scaledPixels(kViewerStripLeastPx, uiScale) / workSize.y, kViewerStrip, 0.45f);
    return s;
}

TileRect tiledRect(EditorWindow window, glm::vec2 workPos, glm::vec2 workSize, float uiScale) {
    LayoutShares const shares = layoutShares(workSize, uiScale);
    // Whole pixels, so neighbouring windows share edges exactly.
    float const leftW = std::floor(workSize.x * shares.left);
    float const rightW = std::floor(workSize.x * shares.right);
    float const centreW = workSize.x - leftW - rightW;
    float const stripH = std::floor(workSize.y * shares.strip);
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
