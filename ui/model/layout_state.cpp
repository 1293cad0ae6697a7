// The default layout's shares and rectangles.
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

char const* dockLayoutName(DockLayoutKind kind) {
    return kind == DockLayoutKind::OneColumn ? "one column" : "two columns";
}

DockLayoutKind chooseDockLayout(glm::vec2 workSize, float uiScale) {
    if (uiScale <= 1.0f || workSize.x <= 0.0f) return DockLayoutKind::TwoColumns;
    float const sides = scaledPixels(kLeftColumnLeastPx, uiScale) + scaledPixels(kRightColumnLeastPx, uiScale);
    return sides <= (1.0f - kViewportHalf) * workSize.x ? DockLayoutKind::TwoColumns : DockLayoutKind::OneColumn;
}

float oneColumnShare(glm::vec2 workSize, float uiScale) {
    if (workSize.x <= 0.0f) return kOneColumnShare;
    float const least = scaledPixels(kOneColumnLeastPx, std::max(uiScale, 1.0f)) / workSize.x;
    return std::min(std::max(kOneColumnShare, least), 1.0f - kViewportHalf);
}

LayoutSplits defaultSplits(glm::vec2 workSize, float uiScale) {
    LayoutShares const shares = layoutShares(workSize, uiScale);
    LayoutSplits s;
    s.left = shares.left;
    s.right = shares.right;
    s.strip = shares.strip;
    s.lights = kLightsShare;
    s.rightRows = {kInspectorShare, kInspectorShare + kLessonsShare, kInspectorShare + kLessonsShare + kStatsShare};
    return s;
}

namespace {

// A share held in [lo, hi]; where the area is too small for both least sizes, the middle.
float holdShare(float v, float lo, float hi) {
    return lo <= hi ? std::clamp(v, lo, hi) : 0.5f * (lo + hi);
}

struct Least {
    float x = 0.0f;     // of the work area's width
    float y = 0.0f;     // of its height
    float band = 0.0f;  // of the band above the strip
};

// Where the area is too small for every least size (a small window at a large scale), the tiles
// share what there is: three across, the strip and four rows down, four rows in the band.
Least leastShares(LayoutSplits const& s, glm::vec2 size, float uiScale) {
    float const px = scaledPixels(kTileLeastPx, std::max(uiScale, 1.0f));
    float const band = size.y - std::floor(size.y * s.strip);
    return {std::min(px / size.x, 1.0f / 3.0f), std::min(px / size.y, 0.2f),
            band > 0.0f ? std::min(px / band, 0.25f) : 0.25f};
}

// Every tile at least its least size, the columns leaving the viewport room, the rows in order.
LayoutSplits held(LayoutSplits s, glm::vec2 size, float uiScale) {
    if (size.x <= 0.0f || size.y <= 0.0f) return s;
    Least m = leastShares(s, size, uiScale);
    s.strip = holdShare(s.strip, m.y, 1.0f - 4.0f * m.y);  // the right column's four rows above it
    m = leastShares(s, size, uiScale);
    s.right = holdShare(s.right, m.x, 1.0f - 2.0f * m.x);
    s.left = holdShare(s.left, m.x, 1.0f - s.right - m.x);
    s.lights = holdShare(s.lights, m.band, 1.0f - m.band);
    s.rightRows[0] = holdShare(s.rightRows[0], m.band, 1.0f - 3.0f * m.band);
    s.rightRows[1] = holdShare(s.rightRows[1], s.rightRows[0] + m.band, 1.0f - 2.0f * m.band);
    s.rightRows[2] = holdShare(s.rightRows[2], s.rightRows[1] + m.band, 1.0f - m.band);
    return s;
}

// The boundaries in whole pixels from the work area's corner, so neighbouring tiles share edges.
struct Edges {
    float leftW = 0.0f;
    float rightW = 0.0f;
    float band = 0.0f;     // the height above the strip
    float lightsH = 0.0f;  // the Lights tile's height
    std::array<float, 3> rows{};
};

Edges edges(glm::vec2 size, float uiScale) {
    LayoutSplits const s = held(defaultSplits(size, uiScale), size, uiScale);
    Edges e;
    e.leftW = std::floor(size.x * s.left);
    e.rightW = std::floor(size.x * s.right);
    e.band = size.y - std::floor(size.y * s.strip);
    e.lightsH = std::floor(e.band * s.lights);
    for (std::size_t i = 0; i < e.rows.size(); ++i) e.rows[i] = std::floor(e.band * s.rightRows[i]);
    return e;
}

}  // namespace

TileRect defaultWindowRect(EditorWindow window, glm::vec2 workPos, glm::vec2 workSize, float uiScale) {
    Edges const e = edges(workSize, uiScale);
    glm::vec2 const p = workPos;
    float const rightX = workSize.x - e.rightW;
    float const centreW = rightX - e.leftW;
    switch (window) {
        case EditorWindow::Lights:
            return {p, {e.leftW, e.lightsH}};
        case EditorWindow::Pipeline:
            return {p + glm::vec2(0, e.lightsH), {e.leftW, e.band - e.lightsH}};
        case EditorWindow::Viewport:
            return {p + glm::vec2(e.leftW, 0), {centreW, e.band}};
        case EditorWindow::GBuffer:
            return {p + glm::vec2(0, e.band), {workSize.x, workSize.y - e.band}};
        case EditorWindow::PixelInspector:
            return {p + glm::vec2(rightX, 0), {e.rightW, e.rows[0]}};
        case EditorWindow::Lessons:
            return {p + glm::vec2(rightX, e.rows[0]), {e.rightW, e.rows[1] - e.rows[0]}};
        case EditorWindow::Stats:
            return {p + glm::vec2(rightX, e.rows[1]), {e.rightW, e.rows[2] - e.rows[1]}};
        case EditorWindow::Log:
            return {p + glm::vec2(rightX, e.rows[2]), {e.rightW, e.band - e.rows[2]}};
    }
    return {};
}

}  // namespace gbl::ui
