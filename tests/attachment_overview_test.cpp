// The attachment overview's cells and grid (model/attachment_overview.h): which views, where each
// picture goes, and which cell a click lands on.
#include "model/attachment_overview.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

using namespace gbl;
using namespace gbl::ui;

namespace {

bool overlap(glm::vec4 a, glm::vec4 b) {
    return a.x < b.x + b.z && b.x < a.x + a.z && a.y < b.y + b.w && b.y < a.y + a.w;
}

// Every picture inside the area with its label line above it, at the frame's aspect (to the pixel
// the rounding down of width and height can cost), and no two overlapping.
void expectTiles(std::vector<glm::vec4> const& rects, glm::vec4 area, float aspect, float label) {
    for (std::size_t i = 0; i < rects.size(); ++i) {
        glm::vec4 const r = rects[i];
        EXPECT_GE(r.y - label, area.y) << i;
        EXPECT_GE(r.x, area.x) << i;
        EXPECT_LE(r.x + r.z, area.x + area.z) << i;
        EXPECT_LE(r.y + r.w, area.y + area.w) << i;
        EXPECT_NEAR(r.z / aspect, r.w, 1.0f) << i;
        for (std::size_t j = i + 1; j < rects.size(); ++j) EXPECT_FALSE(overlap(r, rects[j])) << i << " " << j;
    }
}

}  // namespace

TEST(AttachmentOverview, ShowsTheLitFrameAndEachAttachmentOnce) {
    std::vector<DebugView> const views = overviewViews();
    ASSERT_EQ(views.size(), 6u);
    EXPECT_EQ(views.front(), DebugView::Final);
    std::set<DebugView> const unique(views.begin(), views.end());
    EXPECT_EQ(unique.size(), views.size());
    for (DebugView v :
         {DebugView::Position, DebugView::Normal, DebugView::Albedo, DebugView::Specular, DebugView::DepthLinear})
        EXPECT_TRUE(unique.count(v)) << kDebugViewNames[std::size_t(v)];
    EXPECT_EQ(overviewLabel(DebugView::Normal), "normal");
}

TEST(AttachmentOverview, AWideViewportTakesThreeColumnsOfTwoRows) {
    // The viewport's image at 1280x720: 640x400, the frame at that aspect.
    glm::vec4 const area(300.0f, 100.0f, 640.0f, 400.0f);
    float const aspect = 1.6f, label = 20.0f, gap = 4.0f;
    std::vector<glm::vec4> const rects = overviewImageRects(6, area, aspect, label, gap);
    ASSERT_EQ(rects.size(), 6u);
    expectTiles(rects, area, aspect, label);
    // Three columns: (640 - 2 gaps) / 3 = 210.67 wide, rounded down; 2 rows of 131 + label fit in 400.
    EXPECT_EQ(rects[0].z, 210.0f);
    EXPECT_EQ(rects[0].y, rects[2].y);
    EXPECT_GT(rects[3].y, rects[0].y + rects[0].w);
    // The pictures fill most of the area: the grid is not a row of thumbnails.
    float covered = 0.0f;
    for (glm::vec4 const& r : rects) covered += r.z * r.w;
    EXPECT_GT(covered / (area.z * area.w), 0.6f);
}

TEST(AttachmentOverview, ATallViewportStacksTheCells) {
    glm::vec4 const area(0.0f, 0.0f, 300.0f, 1000.0f);
    std::vector<glm::vec4> const rects = overviewImageRects(6, area, 1.6f, 20.0f, 4.0f);
    ASSERT_EQ(rects.size(), 6u);
    expectTiles(rects, area, 1.6f, 20.0f);
    EXPECT_EQ(rects[0].x, rects[1].x);  // one column
}

TEST(AttachmentOverview, NoCellsWhereNothingFits) {
    EXPECT_TRUE(overviewImageRects(6, glm::vec4(0.0f, 0.0f, 20.0f, 20.0f), 1.6f, 20.0f, 4.0f).empty());
    EXPECT_TRUE(overviewImageRects(0, glm::vec4(0.0f, 0.0f, 640.0f, 400.0f), 1.6f, 20.0f, 4.0f).empty());
    EXPECT_TRUE(overviewImageRects(6, glm::vec4(0.0f, 0.0f, 640.0f, 400.0f), 0.0f, 20.0f, 4.0f).empty());
}

TEST(AttachmentOverview, AClickLandsOnTheCellUnderIt) {
    std::vector<OverviewCell> cells;
    std::vector<DebugView> const views = overviewViews();
    std::vector<glm::vec4> const rects =
        overviewImageRects(int(views.size()), glm::vec4(0.0f, 0.0f, 640.0f, 400.0f), 1.6f, 20.0f, 4.0f);
    for (std::size_t i = 0; i < rects.size(); ++i) cells.push_back({views[i], rects[i]});
    for (std::size_t i = 0; i < cells.size(); ++i) {
        glm::vec4 const r = cells[i].image;
        EXPECT_EQ(overviewCellAt(cells, glm::vec2(r.x + r.z * 0.5f, r.y + r.w * 0.5f)), int(i));
        EXPECT_EQ(overviewCellAt(cells, glm::vec2(r.x, r.y)), int(i));  // first pixel in
        // Just right of the picture: the gap between cells, or past the last column.
        EXPECT_EQ(overviewCellAt(cells, glm::vec2(r.x + r.z, r.y + r.w * 0.5f)), -1);
    }
    // A label line above the first row is no cell.
    EXPECT_EQ(overviewCellAt(cells, glm::vec2(cells[0].image.x + 5.0f, cells[0].image.y - 5.0f)), -1);
}
