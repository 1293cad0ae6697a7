// The default dock layout, built with the DockBuilder API on first start and on View > Reset layout.
#include "panels/layout.h"

#include "panels/fonts.h"
#include "panels/panel_frame.h"

#include <imgui.h>
#include <imgui_internal.h>  // the DockBuilder API

namespace gbl::ui {

namespace {
constexpr char const* kDockSpaceName = "gbl-dockspace";

void buildDefaultDockLayout(ImGuiID dockspace, ImGuiViewport const* viewport) {
    LayoutShares const shares = layoutShares({viewport->WorkSize.x, viewport->WorkSize.y}, uiScaleFactor());
    ImGui::DockBuilderRemoveNode(dockspace);
    ImGui::DockBuilderAddNode(dockspace, ImGuiDockNodeFlags_DockSpace);
    ImGui::DockBuilderSetNodeSize(dockspace, viewport->WorkSize);

    // The G-buffer strip first, along the whole bottom; the columns split what is above it.
    ImGuiID centre = dockspace;
    ImGuiID const strip = ImGui::DockBuilderSplitNode(centre, ImGuiDir_Down, shares.strip, nullptr, &centre);
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
    ImGui::DockBuilderDockWindow(windowName(EditorWindow::GBuffer), strip);
    ImGui::DockBuilderDockWindow(windowName(EditorWindow::Lessons), lessons);
    ImGui::DockBuilderDockWindow(windowName(EditorWindow::Lights), leftTop);
    ImGui::DockBuilderDockWindow(windowName(EditorWindow::Pipeline), leftBottom);
    ImGui::DockBuilderDockWindow(windowName(EditorWindow::PixelInspector), rightTop);
    // Every window gets its own node so all of them are visible at once (no hidden tabs).
    ImGui::DockBuilderDockWindow(windowName(EditorWindow::Stats), stats);
    ImGui::DockBuilderDockWindow(windowName(EditorWindow::Log), log);
    ImGui::DockBuilderDockWindow(kFrameWindowName, strip);  // a tab beside the strip, off by default
    ImGui::DockBuilderFinish(dockspace);
}
}  // namespace

void beginLayout(LayoutState& state) {
    ImGuiViewport const* viewport = ImGui::GetMainViewport();
    ImGuiID const dockspace = ImGui::GetID(kDockSpaceName);
    // A dock tree restored from imgui.ini is kept; a fresh start or "Reset layout" builds ours.
    if (state.resetRequested || ImGui::DockBuilderGetNode(dockspace) == nullptr) {
        buildDefaultDockLayout(dockspace, viewport);
        state.resetRequested = false;
    }
    state.dockBuilt = true;
    ImGui::DockSpaceOverViewport(dockspace, viewport);
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
