// The tiled layout (ImGui without docking) fills the work area exactly, without overlap.
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
                TileRect const r = tiledRect(EditorWindow(i), pos, size, scale);
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
    TileRect const v = tiledRect(EditorWindow::Viewport, {0, 0}, size);
    for (std::size_t i = 1; i < kEditorWindowNames.size(); ++i) {
        TileRect const r = tiledRect(EditorWindow(i), {0, 0}, size);
        EXPECT_GT(v.size.x * v.size.y, r.size.x * r.size.y) << kEditorWindowNames[i];
    }
}

// Issue 26: every attachment readable at once. The strip spans the work area, so each of the five
// viewers gets a fifth of it: 256 px at 1280 wide, room for a 240 px image beside the cell
// padding and borders (the editor's frame log measures the drawn images: ui_layout_fits.sh).
TEST(UiLayout, EachViewerGetsAFifthOfTheWidth) {
    for (glm::vec2 size : {glm::vec2(1280, 701), glm::vec2(1600, 881)}) {
        TileRect const strip = tiledRect(EditorWindow::GBuffer, {0, 19}, size);
        EXPECT_EQ(strip.size.x, size.x);
        EXPECT_GE(strip.size.x / 5.0f, 250.0f) << size.x;
        // Tall enough for the one-line toolbar over an image of the frame's aspect at 240 px.
        EXPECT_GE(strip.size.y, 200.0f) << size.y;
        TileRect const v = tiledRect(EditorWindow::Viewport, {0, 19}, size);
        EXPECT_GE(v.size.x, 0.4f * size.x);
        EXPECT_GE(v.size.y, 0.4f * (size.y + 19.0f));
    }
}

// UI scale (issue 26): at 1.5 the side columns and the strip grow with the text from their
// least sizes at scale 1, and the viewport keeps at least kViewportLeast of the width.
TEST(UiLayout, ColumnsGrowWithTheUiScale) {
    glm::vec2 const pos(0, 19);
    glm::vec2 const size(1600, 881);
    TileRect const lights = tiledRect(EditorWindow::Lights, pos, size, 1.5f);
    TileRect const inspector = tiledRect(EditorWindow::PixelInspector, pos, size, 1.5f);
    TileRect const strip = tiledRect(EditorWindow::GBuffer, pos, size, 1.5f);
    TileRect const viewport = tiledRect(EditorWindow::Viewport, pos, size, 1.5f);
    EXPECT_EQ(lights.size.x, 450.0f);     // 300 px at scale 1, times 1.5
    EXPECT_EQ(inspector.size.x, 480.0f);  // 320 px times 1.5
    EXPECT_EQ(strip.size.y, 312.0f);      // 208 px times 1.5
    EXPECT_EQ(viewport.size.x, 1600.0f - 450.0f - 480.0f);
    // At scale 3 the columns would leave the viewport too little: they share what it leaves.
    TileRect const wide = tiledRect(EditorWindow::Viewport, pos, size, 3.0f);
    EXPECT_GE(wide.size.x, std::floor(kViewportLeast * size.x));
    // At scale 1 the fractions hold, whatever the size (a small window's columns are not widened).
    glm::vec2 const small(640, 461);
    EXPECT_EQ(tiledRect(EditorWindow::Lights, pos, small, 1.0f).size.x, std::floor(640.0f * kLeftColumn));
    EXPECT_EQ(tiledRect(EditorWindow::GBuffer, pos, small, 1.0f).size.y, std::floor(461.0f * kViewerStrip));
}

// Issue 26 (Debian's ImGui 1.86 has no docking): the user drags the tiled layout's boundaries.
namespace {
TileRect tile(EditorWindow w, std::optional<LayoutSplits> const& s) {
    return tiledRect(w, {0, 19}, {1280, 701}, 1.0f, s);
}
glm::vec2 handleCentre(Split split, std::optional<LayoutSplits> const& s) {
    TileRect const h = splitHandles({0, 19}, {1280, 701}, 1.0f, s)[std::size_t(split)];
    return h.pos + 0.5f * h.size;
}
LayoutSplits drag(std::optional<LayoutSplits> const& s, Split split, glm::vec2 by) {
    return dragSplit(s, split, handleCentre(split, s) + by, {0, 19}, {1280, 701}, 1.0f);
}
}  // namespace

TEST(UiLayout, DefaultSplitsGiveTheDefaultTiles) {
    glm::vec2 const size(1280, 701);
    LayoutSplits const d = defaultSplits(size, 1.0f);
    for (std::size_t i = 0; i < kEditorWindowNames.size(); ++i) {
        TileRect const a = tiledRect(EditorWindow(i), {0, 19}, size, 1.0f);
        TileRect const b = tiledRect(EditorWindow(i), {0, 19}, size, 1.0f, d);
        EXPECT_EQ(a.pos, b.pos) << kEditorWindowNames[i];
        EXPECT_EQ(a.size, b.size) << kEditorWindowNames[i];
    }
    // Each handle lies on the boundary between its two windows.
    auto const handles = splitHandles({0, 19}, size, 1.0f, std::nullopt);
    EXPECT_FLOAT_EQ(handleCentre(Split::LeftColumn, std::nullopt).x, tile(EditorWindow::Viewport, std::nullopt).pos.x);
    EXPECT_FLOAT_EQ(handleCentre(Split::Strip, std::nullopt).y, tile(EditorWindow::GBuffer, std::nullopt).pos.y);
    EXPECT_FLOAT_EQ(handleCentre(Split::StatsRow, std::nullopt).y, tile(EditorWindow::Log, std::nullopt).pos.y);
    for (TileRect const& h : handles) EXPECT_EQ(std::min(h.size.x, h.size.y), kSplitHandlePx);
}

TEST(UiLayout, DraggingABoundaryMovesOnlyThatBoundary) {
    std::optional<LayoutSplits> const none;
    // The strip's top 100 px up: the strip grows by 100, the band above shrinks by as much.
    LayoutSplits const up = drag(none, Split::Strip, {0, -100});
    EXPECT_NEAR(tile(EditorWindow::GBuffer, up).size.y, tile(EditorWindow::GBuffer, none).size.y + 100.0f, 1.0f);
    EXPECT_NEAR(tile(EditorWindow::Viewport, up).size.y, tile(EditorWindow::Viewport, none).size.y - 100.0f, 1.0f);
    EXPECT_EQ(tile(EditorWindow::Viewport, up).size.x, tile(EditorWindow::Viewport, none).size.x);
    // The Lessons/Stats boundary 20 px down: Lessons grows, Stats shrinks, the others stay.
    LayoutSplits const lessons = drag(none, Split::LessonsRow, {0, 20});
    EXPECT_NEAR(tile(EditorWindow::Lessons, lessons).size.y, tile(EditorWindow::Lessons, none).size.y + 20.0f, 1.0f);
    EXPECT_NEAR(tile(EditorWindow::Stats, lessons).size.y, tile(EditorWindow::Stats, none).size.y - 20.0f, 1.0f);
    for (EditorWindow w : {EditorWindow::PixelInspector, EditorWindow::Log, EditorWindow::Viewport}) {
        EXPECT_EQ(tile(w, lessons).pos, tile(w, none).pos) << windowName(w);
        EXPECT_EQ(tile(w, lessons).size, tile(w, none).size) << windowName(w);
    }
    // The right column's edge 80 px left: it widens, the viewport narrows, the left column stays.
    LayoutSplits const right = drag(none, Split::RightColumn, {-80, 0});
    EXPECT_NEAR(tile(EditorWindow::Stats, right).size.x, tile(EditorWindow::Stats, none).size.x + 80.0f, 1.0f);
    EXPECT_EQ(tile(EditorWindow::Lights, right).size.x, tile(EditorWindow::Lights, none).size.x);
}

TEST(UiLayout, ABoundaryStopsWhereANeighbourReachesItsLeastSize) {
    std::optional<LayoutSplits> const none;
    // The left column dragged to the window's edge keeps its least width; dragged into the right
    // column, it leaves the viewport its least width and does not move the right column.
    EXPECT_NEAR(tile(EditorWindow::Lights, drag(none, Split::LeftColumn, {-2000, 0})).size.x, kTileLeastPx, 1.0f);
    LayoutSplits const wide = drag(none, Split::LeftColumn, {2000, 0});
    EXPECT_NEAR(tile(EditorWindow::Viewport, wide).size.x, kTileLeastPx, 1.0f);
    EXPECT_EQ(tile(EditorWindow::Stats, wide).size.x, tile(EditorWindow::Stats, none).size.x);
    // A row boundary dragged past the next one stops the least height above it.
    LayoutSplits const rows = drag(none, Split::InspectorRow, {0, 2000});
    EXPECT_NEAR(tile(EditorWindow::Lessons, rows).size.y, kTileLeastPx, 1.0f);
    EXPECT_EQ(tile(EditorWindow::Stats, rows).size.y, tile(EditorWindow::Stats, none).size.y);
    // Whatever was dragged, the tiles still cover the work area without overlap.
    for (LayoutSplits const& s :
         {wide, rows, drag(none, Split::Strip, {0, -2000}), drag(none, Split::LightsRow, {0, 2000})}) {
        float area = 0.0f;
        for (std::size_t i = 0; i < kEditorWindowNames.size(); ++i) {
            TileRect const r = tile(EditorWindow(i), s);
            EXPECT_GE(std::min(r.size.x, r.size.y), kTileLeastPx - 1.0f) << kEditorWindowNames[i];
            area += r.size.x * r.size.y;
            for (std::size_t j = i + 1; j < kEditorWindowNames.size(); ++j)
                EXPECT_EQ(overlap(r, tile(EditorWindow(j), s)), 0.0f);
        }
        EXPECT_FLOAT_EQ(area, 1280.0f * 701.0f);
    }
}

TEST(UiLayout, SplitsLineReadsBackAndBadLinesAreRefusedNamingTheKey) {
    LayoutSplits const s = drag(std::nullopt, Split::Strip, {0, -60});
    std::string const line = splitsLine(s);
    ASSERT_EQ(line.substr(0, kSplitsKey.size() + 1), std::string(kSplitsKey) + "=");
    auto const back = parseSplits(std::string_view(line).substr(kSplitsKey.size() + 1), "imgui.ini: Splits");
    ASSERT_TRUE(back);
    EXPECT_NEAR(back->strip, s.strip, 1e-4f);
    EXPECT_NEAR(back->rightRows[2], s.rightRows[2], 1e-4f);
    for (char const* bad : {"", "0.2,0.2,0.3", "0.2,0.2,0.3,0.5,0.3,0.7,0.9,0.95", "0.6,0.5,0.3,0.5,0.3,0.7,0.9",
                            "0.2,0.2,0.3,0.5,0.7,0.3,0.9", "0.2,0.2,nan,0.5,0.3,0.7,0.9", "0.2,0.2,0.3,0.5,0.3,0.7,1.5",
                            "0.2;0.2;0.3;0.5;0.3;0.7;0.9", "0.2,0.2,0.3,0.5,0.3,0.7,0.9x"}) {
        std::string error;
        EXPECT_FALSE(parseSplits(bad, "imgui.ini: Splits", &error)) << bad;
        EXPECT_NE(error.find("imgui.ini: Splits must be seven shares"), std::string::npos) << error;
    }
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
