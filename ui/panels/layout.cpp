// The default dock layout, built with the DockBuilder API on first start and on View > Reset layout.
#include "panels/layout.h"

#include "panels/fonts.h"
#include "panels/panel_frame.h"

#include <imgui.h>
#include <imgui_internal.h>  // the DockBuilder API

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <vector>

namespace gbl::ui {

namespace {
constexpr char const* kDockSpaceName = "gbl-dockspace";
// Frames after a layout is built (or the window resized) in which the strip's height is fitted to
// its images: the viewport's image, whose aspect the viewers show, changes with each fit.
constexpr int kStripFitFrames = 8;

// At scale 1 the strip keeps its share (kViewerStrip, tuned for the images at 1280x720), so a frame's
// size is the same from the first frame on, as scripts and captures expect; a larger scale fits it.
int stripFitFrames(float scale) {
    return scale > 1.0f ? kStripFitFrames : 0;
}

// Docks `windows` as tabs of `node`, in this order, the first one shown.
void dockTabs(ImGuiID node, std::initializer_list<EditorWindow> windows) {
    short order = 0;
    for (EditorWindow w : windows) {
        char const* name = windowName(w);
        ImGui::DockBuilderDockWindow(name, node);
        // The tab bar sorts new tabs by their dock order, which DockBuilderDockWindow clears.
        if (ImGuiWindow* window = ImGui::FindWindowByName(name))
            window->DockOrder = order;
        else if (ImGuiWindowSettings* settings = ImGui::FindWindowSettingsByID(ImHashStr(name)))
            settings->DockOrder = order;
        ++order;
    }
    // A window's tab ID is "#TAB" in its own ID scope (ImGuiWindow's constructor).
    if (ImGuiDockNode* n = ImGui::DockBuilderGetNode(node))
        n->SelectedTabId = ImHashStr("#TAB", 0, ImHashStr(windowName(*windows.begin())));
}

void buildTwoColumnLayout(ImGuiID dockspace, glm::vec2 work, ImGuiID& strip) {
    LayoutShares const shares = layoutShares(work, uiScaleFactor());
    // The G-buffer strip first, along the whole bottom; the columns split what is above it.
    ImGuiID centre = dockspace;
    strip = ImGui::DockBuilderSplitNode(centre, ImGuiDir_Down, shares.strip, nullptr, &centre);
    ImGuiID const left = ImGui::DockBuilderSplitNode(centre, ImGuiDir_Left, shares.left, nullptr, &centre);
    // The right column is a share of what is left after the left column was taken.
    ImGuiID const right =
        ImGui::DockBuilderSplitNode(centre, ImGuiDir_Right, shares.right / (1.0f - shares.left), nullptr, &centre);
    ImGuiID leftTop = left;
    ImGuiID const leftBottom =
        ImGui::DockBuilderSplitNode(leftTop, ImGuiDir_Down, 1.0f - kLightsShare, nullptr, &leftTop);
    // Each split below takes its share of what is still left of the right column.
    ImGuiID rightTop = right;
    ImGuiID lessons = ImGui::DockBuilderSplitNode(rightTop, ImGuiDir_Down, 1.0f - kInspectorShare, nullptr, &rightTop);
    float const belowLessons = 1.0f - kInspectorShare - kLessonsShare;
    ImGuiID stats =
        ImGui::DockBuilderSplitNode(lessons, ImGuiDir_Down, belowLessons / (1.0f - kInspectorShare), nullptr, &lessons);
    ImGuiID const log =
        ImGui::DockBuilderSplitNode(stats, ImGuiDir_Down, 1.0f - kStatsShare / belowLessons, nullptr, &stats);

    ImGui::DockBuilderDockWindow(windowName(EditorWindow::Viewport), centre);
    ImGui::DockBuilderDockWindow(windowName(EditorWindow::Lessons), lessons);
    ImGui::DockBuilderDockWindow(windowName(EditorWindow::Lights), leftTop);
    ImGui::DockBuilderDockWindow(windowName(EditorWindow::Pipeline), leftBottom);
    ImGui::DockBuilderDockWindow(windowName(EditorWindow::PixelInspector), rightTop);
    // Every window gets its own node so all of them are visible at once (no hidden tabs).
    ImGui::DockBuilderDockWindow(windowName(EditorWindow::Stats), stats);
    ImGui::DockBuilderDockWindow(windowName(EditorWindow::Log), log);
}

// At a large UI scale: one side column on the right, its upper node the tools (Lights first, the
// plot under the light list), its lower node the lesson (Lessons first) with Stats and Log.
void buildOneColumnLayout(ImGuiID dockspace, glm::vec2 work, ImGuiID& strip) {
    float const scale = uiScaleFactor();
    ImGuiID centre = dockspace;
    strip = ImGui::DockBuilderSplitNode(centre, ImGuiDir_Down, layoutShares(work, scale).strip, nullptr, &centre);
    ImGuiID top = ImGui::DockBuilderSplitNode(centre, ImGuiDir_Right, oneColumnShare(work, scale), nullptr, &centre);
    ImGuiID const bottom = ImGui::DockBuilderSplitNode(top, ImGuiDir_Down, 1.0f - kOneColumnTopShare, nullptr, &top);
    ImGui::DockBuilderDockWindow(windowName(EditorWindow::Viewport), centre);
    dockTabs(top, {EditorWindow::Lights, EditorWindow::Pipeline, EditorWindow::PixelInspector});
    dockTabs(bottom, {EditorWindow::Lessons, EditorWindow::Stats, EditorWindow::Log});
}

void buildDefaultDockLayout(ImGuiID dockspace, ImGuiViewport const* viewport, DockLayoutKind kind) {
    glm::vec2 const work{viewport->WorkSize.x, viewport->WorkSize.y};
    ImGui::DockBuilderRemoveNode(dockspace);
    ImGui::DockBuilderAddNode(dockspace, ImGuiDockNodeFlags_DockSpace);
    ImGui::DockBuilderSetNodeSize(dockspace, viewport->WorkSize);
    ImGuiID strip = 0;
    if (kind == DockLayoutKind::OneColumn)
        buildOneColumnLayout(dockspace, work, strip);
    else
        buildTwoColumnLayout(dockspace, work, strip);
    dockTabs(strip, {EditorWindow::GBuffer});
    ImGui::DockBuilderDockWindow(kFrameWindowName, strip);  // a tab beside the strip, off by default
    ImGui::DockBuilderFinish(dockspace);
}

// Whether the tree was built for another scale or the work area now asks for the other kind. A
// minimised window (no work area) keeps what it had.
bool layoutStale(LayoutState const& state, glm::vec2 work, float scale, DockLayoutKind kind) {
    if (state.builtScale <= 0.0f || work.x <= 0.0f || work.y <= 0.0f) return false;
    return std::abs(state.builtScale - scale) > 0.005f || state.builtKind != kind;
}
}  // namespace

void beginLayout(LayoutState& state) {
    ImGuiViewport const* viewport = ImGui::GetMainViewport();
    ImGuiID const dockspace = ImGui::GetID(kDockSpaceName);
    glm::vec2 const work{viewport->WorkSize.x, viewport->WorkSize.y};
    float const scale = uiScaleFactor();
    DockLayoutKind const kind = chooseDockLayout(work, scale);
    // A dock tree restored from imgui.ini is kept while it was built for this scale (or the file did
    // not say); a fresh start, "Reset layout", a scale change or a size that asks for the other kind
    // builds ours.
    if (state.resetRequested || ImGui::DockBuilderGetNode(dockspace) == nullptr ||
        layoutStale(state, work, scale, kind)) {
        buildDefaultDockLayout(dockspace, viewport, kind);
        state.resetRequested = false;
        state.builtKind = kind;
        state.builtScale = scale;
        state.stripFit = {stripFitFrames(scale), work};
        // The fitted windows' saved heights were of the old tree's nodes: fit again in the new one.
        state.lessonFit = {};
        state.lightsFit = {};
    } else if (state.builtScale <= 0.0f) {
        state.builtKind = kind;  // a tree from an older layout file: taken as made for this scale
        state.builtScale = scale;
    }
    if (work != state.stripFit.workSize && work.x > 0.0f && work.y > 0.0f)
        state.stripFit = {stripFitFrames(scale), work};
    state.dockBuilt = true;
    // The presentation layout keeps the dock tree (every window's place) alive without drawing it or
    // its host window (which would cover the presentation window).
    if (state.presentation)
        ImGui::DockSpace(dockspace, ImVec2(0.0f, 0.0f), ImGuiDockNodeFlags_KeepAliveOnly);
    else
        ImGui::DockSpaceOverViewport(dockspace, viewport);
}

namespace {

// The leaves below a dock node (1 for a leaf).
int leafCount(ImGuiDockNode const* node) {
    if (!node->IsSplitNode()) return 1;
    return leafCount(node->ChildNodes[0]) + leafCount(node->ChildNodes[1]);
}

void keepHeight(DockHeightFit& fit, ImGuiDockNode const* node) {
    for (auto const& [id, h] : fit.saved)
        if (id == node->ID) return;
    fit.saved.emplace_back(node->ID, node->SizeRef.y);
}

// Grows the window's node by up to `need` pixels, taken from its column's other nodes (each keeps
// its tab and `keepLines` lines), nearest first: a split's two children share its height by their SizeRef, so at each
// level the side holding the window gets what this level and the ones above give, the other side loses its part.
void growNode(DockHeightFit& fit, EditorWindow which, float need, int keepLines) {
    ImGuiWindow const* window = ImGui::FindWindowByName(windowName(which));
    if (!window || !window->DockIsActive || !window->DockNode) return;
    float const keep = ImGui::GetFrameHeight() + ImGui::GetTextLineHeightWithSpacing() * float(keepLines) +
                       ImGui::GetStyle().WindowPadding.y * 2.0f;  // a tab and its lines
    struct Level {
        ImGuiDockNode* mine;
        ImGuiDockNode* other;
        float take;
    };
    std::vector<Level> levels;
    for (ImGuiDockNode* n = window->DockNode; n->ParentNode && need > 0.5f; n = n->ParentNode) {
        ImGuiDockNode* parent = n->ParentNode;
        if (parent->SplitAxis != ImGuiAxis_Y) break;  // the column ends here
        ImGuiDockNode* other = parent->ChildNodes[0] == n ? parent->ChildNodes[1] : parent->ChildNodes[0];
        float const take = std::min(need, std::max(0.0f, other->Size.y - keep * float(leafCount(other))));
        levels.push_back({n, other, take});
        need -= take;
    }
    float above = 0.0f;  // what the levels above the current one give
    for (auto it = levels.rbegin(); it != levels.rend(); ++it) {
        above += it->take;
        keepHeight(fit, it->mine);
        keepHeight(fit, it->other);
        it->mine->SizeRef.y = it->mine->Size.y + above;
        it->other->SizeRef.y = it->other->Size.y - it->take;
    }
}

}  // namespace

void fitWindowHeight(DockHeightFit& fit, EditorWindow which, bool lessonOpen, long key, float shortPx, int keepLines) {
    ImGuiViewport const* viewport = ImGui::GetMainViewport();
    glm::vec2 const work{viewport->WorkSize.x, viewport->WorkSize.y};
    if (lessonOpen && (!fit.wasOpen || key != fit.key || work != fit.workSize || uiScaleFactor() != fit.scale))
        fit.triesLeft = 3;
    fit.key = key;
    if (!lessonOpen && fit.wasOpen) {
        // The column's heights as they were before the lesson grew it, where those nodes remain.
        for (auto const& [id, h] : fit.saved)
            if (ImGuiDockNode* node = ImGui::DockBuilderGetNode(id)) node->SizeRef.y = h;
        fit.saved.clear();
        fit.triesLeft = 0;
    }
    fit.wasOpen = lessonOpen;
    fit.workSize = work;
    fit.scale = uiScaleFactor();
    if (!lessonOpen || fit.triesLeft <= 0) return;
    --fit.triesLeft;
    if (shortPx > 0.5f) growNode(fit, which, shortPx, keepLines);
}

void fitStripHeight(StripFit& fit, glm::vec2 imageArea, glm::ivec2 frameSize) {
    if (fit.triesLeft <= 0) return;
    --fit.triesLeft;
    if (imageArea.x < 4.0f || imageArea.y < 4.0f || frameSize.x <= 0 || frameSize.y <= 0) return;
    ImGuiWindow const* window = ImGui::FindWindowByName(windowName(EditorWindow::GBuffer));
    if (!window || !window->DockIsActive || !window->DockNode) return;
    ImGuiDockNode* strip = window->DockNode;
    ImGuiDockNode* parent = strip->ParentNode;
    if (!parent || parent->SplitAxis != ImGuiAxis_Y) return;  // undocked from the bottom by the user
    ImGuiDockNode* band = parent->ChildNodes[0] == strip ? parent->ChildNodes[1] : parent->ChildNodes[0];
    // The image at the cell's width, the frame's aspect: the height it needs more (or has spare).
    float const want = imageArea.x * float(frameSize.y) / float(frameSize.x) - imageArea.y;
    // The strip keeps at least a tenth of the work area, never more than half of it.
    float const height = std::clamp(strip->Size.y + want, 0.1f * parent->Size.y, 0.5f * parent->Size.y);
    float const change = std::round(height - strip->Size.y);
    if (std::abs(change) < 2.0f) return;
    strip->SizeRef.y = strip->Size.y + change;
    band->SizeRef.y = band->Size.y - change;
}

void recordDocks(LayoutState& state) {
    for (std::size_t i = 0; i < state.docks.size(); ++i) {
        WindowDock& d = state.docks[i];
        d = {};
        ImGuiWindow const* window = ImGui::FindWindowByName(kEditorWindowNames[i].data());
        if (!window || !window->Active) continue;  // not begun this frame (closed)
        d.dockId = window->DockIsActive ? window->DockId : 0u;
        ImRect const r = window->DockIsActive ? window->DC.DockTabItemRect : window->TitleBarRect();
        d.tab = {r.Min.x, r.Min.y, r.GetWidth(), r.GetHeight()};
    }
}

void placeFrameWindow() {
    // Docked beside the strip by the default layout; a layout restored from an older imgui.ini has
    // no place for it, so it floats at a size that shows a few passes until docked.
    ImGuiViewport const* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowSize(ImVec2(viewport->WorkSize.x * 0.8f, viewport->WorkSize.y * kViewerStrip),
                             ImGuiCond_FirstUseEver);
}

}  // namespace gbl::ui
