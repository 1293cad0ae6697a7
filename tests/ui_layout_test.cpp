// The default dock layout's rectangles fill the work area exactly, without overlap, and give the
// images their space.
#include "model/layout_state.h"
#include "model/window_fit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace gbl::ui;

namespace {
float overlap(TileRect const& a, TileRect const& b) {
    float const w = std::min(a.pos.x + a.size.x, b.pos.x + b.size.x) - std::max(a.pos.x, b.pos.x);
    float const h = std::min(a.pos.y + a.size.y, b.pos.y + b.size.y) - std::max(a.pos.y, b.pos.y);
    return std::max(w, 0.0f) * std::max(h, 0.0f);
}
}  // namespace

TEST(UiLayout, TilesCoverTheWorkAreaWithoutOverlap) {
    for (float scale : {1.0f, 1.5f, 3.0f})
        for (glm::vec2 size : {glm::vec2(1600, 881), glm::vec2(1280, 701), glm::vec2(1023, 767), glm::vec2(640, 461)}) {
            glm::vec2 const pos(0, 19);  // below the main menu bar
            float area = 0.0f;
            std::vector<TileRect> rects;
            for (std::size_t i = 0; i < kEditorWindowNames.size(); ++i) {
                TileRect const r = defaultWindowRect(EditorWindow(i), pos, size, scale);
                EXPECT_GT(r.size.x, 0.0f) << kEditorWindowNames[i];
                EXPECT_GT(r.size.y, 0.0f) << kEditorWindowNames[i];
                EXPECT_GE(r.pos.x, pos.x);
                EXPECT_GE(r.pos.y, pos.y);
                EXPECT_LE(r.pos.x + r.size.x, pos.x + size.x);
                EXPECT_LE(r.pos.y + r.size.y, pos.y + size.y);
                area += r.size.x * r.size.y;
                rects.push_back(r);
            }
            EXPECT_FLOAT_EQ(area, size.x * size.y) << size.x << "x" << size.y << " at scale " << scale;
            for (std::size_t i = 0; i < rects.size(); ++i)
                for (std::size_t j = i + 1; j < rects.size(); ++j)
                    EXPECT_EQ(overlap(rects[i], rects[j]), 0.0f)
                        << kEditorWindowNames[i] << " / " << kEditorWindowNames[j];
        }
}

TEST(UiLayout, ViewportIsTheLargestWindow) {
    glm::vec2 const size(1600, 880);
    TileRect const v = defaultWindowRect(EditorWindow::Viewport, {0, 0}, size);
    for (std::size_t i = 1; i < kEditorWindowNames.size(); ++i) {
        TileRect const r = defaultWindowRect(EditorWindow(i), {0, 0}, size);
        EXPECT_GT(v.size.x * v.size.y, r.size.x * r.size.y) << kEditorWindowNames[i];
    }
}

// Issue 26: every attachment readable at once. The strip spans the work area, so each of the five
// viewers gets a fifth of it: 256 px at 1280 wide, room for a 240 px image beside the cell
// padding and borders (the editor's frame log measures the drawn images: ui_layout_fits.sh).
TEST(UiLayout, EachViewerGetsAFifthOfTheWidth) {
    for (glm::vec2 size : {glm::vec2(1280, 701), glm::vec2(1600, 881)}) {
        TileRect const strip = defaultWindowRect(EditorWindow::GBuffer, {0, 19}, size);
        EXPECT_EQ(strip.size.x, size.x);
        EXPECT_GE(strip.size.x / 5.0f, 250.0f) << size.x;
        // Tall enough for the one-line toolbar over an image of the frame's aspect at 240 px.
        EXPECT_GE(strip.size.y, 200.0f) << size.y;
        TileRect const v = defaultWindowRect(EditorWindow::Viewport, {0, 19}, size);
        EXPECT_GE(v.size.x, 0.4f * size.x);
        EXPECT_GE(v.size.y, 0.4f * (size.y + 19.0f));
    }
}

// UI scale (issue 26): at 1.5 the side columns and the strip grow with the text from their
// least sizes at scale 1, and the viewport keeps at least kViewportLeast of the width.
TEST(UiLayout, ColumnsGrowWithTheUiScale) {
    glm::vec2 const pos(0, 19);
    glm::vec2 const size(1600, 881);
    TileRect const lights = defaultWindowRect(EditorWindow::Lights, pos, size, 1.5f);
    TileRect const inspector = defaultWindowRect(EditorWindow::PixelInspector, pos, size, 1.5f);
    TileRect const strip = defaultWindowRect(EditorWindow::GBuffer, pos, size, 1.5f);
    TileRect const viewport = defaultWindowRect(EditorWindow::Viewport, pos, size, 1.5f);
    EXPECT_EQ(lights.size.x, 450.0f);     // 300 px at scale 1, times 1.5
    EXPECT_EQ(inspector.size.x, 480.0f);  // 320 px times 1.5
    EXPECT_EQ(strip.size.y, 312.0f);      // 208 px times 1.5
    EXPECT_EQ(viewport.size.x, 1600.0f - 450.0f - 480.0f);
    // At scale 3 the columns would leave the viewport too little: they share what it leaves.
    TileRect const wide = defaultWindowRect(EditorWindow::Viewport, pos, size, 3.0f);
    EXPECT_GE(wide.size.x, std::floor(kViewportLeast * size.x));
    // At scale 1 the fractions hold, whatever the size (a small window's columns are not widened).
    glm::vec2 const small(640, 461);
    EXPECT_EQ(defaultWindowRect(EditorWindow::Lights, pos, small, 1.0f).size.x, std::floor(640.0f * kLeftColumn));
    EXPECT_EQ(defaultWindowRect(EditorWindow::GBuffer, pos, small, 1.0f).size.y, std::floor(461.0f * kViewerStrip));
}

// Issue 46: two side columns while both leave the viewport half the width, else one column that
// holds its windows' rows at the scale and still leaves the viewport half the width.
TEST(UiLayout, LargeScalesGetOneSideColumn) {
    glm::vec2 const hd(1280, 701), wide(1600, 881);
    EXPECT_EQ(chooseDockLayout(hd, 1.0f), DockLayoutKind::TwoColumns);
    EXPECT_EQ(chooseDockLayout(wide, 1.0f), DockLayoutKind::TwoColumns);
    EXPECT_EQ(chooseDockLayout({640, 461}, 1.0f), DockLayoutKind::TwoColumns);  // scale 1: as before
    EXPECT_EQ(chooseDockLayout(hd, 1.25f), DockLayoutKind::OneColumn);          // 375 + 400 px > 640
    EXPECT_EQ(chooseDockLayout(wide, 1.25f), DockLayoutKind::TwoColumns);       // 375 + 400 px <= 800
    for (float scale : {1.5f, 2.0f}) {
        for (glm::vec2 size : {hd, wide}) {
            EXPECT_EQ(chooseDockLayout(size, scale), DockLayoutKind::OneColumn) << size.x << " at " << scale;
            float const column = oneColumnShare(size, scale) * size.x;
            EXPECT_GE(column, scaledPixels(kOneColumnLeastPx, scale)) << size.x << " at " << scale;
            EXPECT_LE(column, kViewportHalf * size.x) << size.x << " at " << scale;
        }
    }
    EXPECT_FLOAT_EQ(oneColumnShare(wide, 1.5f), kOneColumnShare);      // 426 px least, 480 px share
    EXPECT_FLOAT_EQ(oneColumnShare({800, 600}, 3.0f), kViewportHalf);  // the viewport keeps half
    EXPECT_STREQ(dockLayoutName(DockLayoutKind::OneColumn), "one column");
}

// The first window without --size: 1600x900 on a 1280x720 screen opens at the screen's size,
// a larger screen keeps 1600x900, a 2x content scale halves what fits.
namespace {
void expectFit(WindowFit const& fit, int width, int height, bool reduced) {
    EXPECT_EQ(fit.width, width);
    EXPECT_EQ(fit.height, height);
    EXPECT_EQ(fit.reduced, reduced);
}
}  // namespace

TEST(WindowFit, TheDefaultWindowShrinksToASmallScreenOnly) {
    expectFit(fitWindowToWorkArea(1600, 900, 1280, 720, 1.0f), 1280, 720, true);
    expectFit(fitWindowToWorkArea(1600, 900, 1920, 1080, 1.0f), 1600, 900, false);
    expectFit(fitWindowToWorkArea(1600, 900, 2560, 800, 1.0f), 1600, 800, true);  // only the height is short
    expectFit(fitWindowToWorkArea(1600, 900, 2560, 1400, 2.0f), 1280, 700, true);
}

TEST(WindowFit, AnUnknownWorkAreaOrScaleLeavesTheSizeAsked) {
    expectFit(fitWindowToWorkArea(1600, 900, 0, 0, 1.0f), 1600, 900, false);
    expectFit(fitWindowToWorkArea(1600, 900, 1280, 720, std::nanf("")), 1280, 720, true);
}
