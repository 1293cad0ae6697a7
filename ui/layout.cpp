// Default dock layout (DockBuilder) and the tiled fallback for ImGui builds without docking.
#include "layout.h"

#include "gui_compat.h"

#include <imgui.h>
#ifdef IMGUI_HAS_DOCK
#include <imgui_internal.h>
#endif

#include <cmath>

namespace gbl::ui {

TileRect tiledRect(EditorWindow window, glm::vec2 workPos, glm::vec2 workSize) {
    // Whole pixels, so neighbouring windows share edges exactly.
    float const leftW = std::floor(workSize.x * kLeftColumn);
    float const rightW = std::floor(workSize.x * kRightColumn);
    float const centreW = workSize.x - leftW - rightW;
    float const h = workSize.y;
    float const stripH = std::floor(h * kViewerStrip);
    float const leftTopH = std::floor(h * 0.64f);
    float const rightTopH = std::floor(h * 0.52f);
    float const statsH = std::floor(h * 0.30f);
    glm::vec2 const p = workPos;
    switch (window) {
    case EditorWindow::Lights: return {p, {leftW, leftTopH}};
    case EditorWindow::Pipeline: return {p + glm::vec2(0, leftTopH), {leftW, h - leftTopH}};
    case EditorWindow::Viewport: return {p + glm::vec2(leftW, 0), {centreW, h - stripH}};
    case EditorWindow::GBuffer: return {p + glm::vec2(leftW, h - stripH), {centreW, stripH}};
    case EditorWindow::PixelInspector: return {p + glm::vec2(leftW + centreW, 0), {rightW, rightTopH}};
    case EditorWindow::Stats: return {p + glm::vec2(leftW + centreW, rightTopH), {rightW, statsH}};
    case EditorWindow::Log:
        return {p + glm::vec2(leftW + centreW, rightTopH + statsH), {rightW, h - rightTopH - statsH}};
    }
    return {};
}

#ifdef IMGUI_HAS_DOCK

namespace {
constexpr char const* kDockSpaceName = "gbl-dockspace";

void buildDefaultDockLayout(ImGuiID dockspace, ImGuiViewport const* viewport) {
    ImGui::DockBuilderRemoveNode(dockspace);
    ImGui::DockBuilderAddNode(dockspace, ImGuiDockNodeFlags_DockSpace);
    ImGui::DockBuilderSetNodeSize(dockspace, viewport->WorkSize);

    ImGuiID centre = dockspace;
    ImGuiID const left = ImGui::DockBuilderSplitNode(centre, ImGuiDir_Left, kLeftColumn, nullptr, &centre);
    // The right column is a share of what is left after the left column was taken.
    ImGuiID const right =
        ImGui::DockBuilderSplitNode(centre, ImGuiDir_Right, kRightColumn / (1.0f - kLeftColumn), nullptr, &centre);
    ImGuiID const strip = ImGui::DockBuilderSplitNode(centre, ImGuiDir_Down, kViewerStrip, nullptr, &centre);
    ImGuiID leftTop = left;
    ImGuiID const leftBottom = ImGui::DockBuilderSplitNode(leftTop, ImGuiDir_Down, 0.36f, nullptr, &leftTop);
    ImGuiID rightTop = right;
    ImGuiID rightMiddle = ImGui::DockBuilderSplitNode(rightTop, ImGuiDir_Down, 0.48f, nullptr, &rightTop);
    ImGuiID const rightBottom = ImGui::DockBuilderSplitNode(rightMiddle, ImGuiDir_Down, 0.38f, nullptr, &rightMiddle);

    ImGui::DockBuilderDockWindow(windowName(EditorWindow::Viewport), centre);
    ImGui::DockBuilderDockWindow(windowName(EditorWindow::GBuffer), strip);
    ImGui::DockBuilderDockWindow(windowName(EditorWindow::Lights), leftTop);
    ImGui::DockBuilderDockWindow(windowName(EditorWindow::Pipeline), leftBottom);
    ImGui::DockBuilderDockWindow(windowName(EditorWindow::PixelInspector), rightTop);
    // Every window gets its own node so all of them are visible at once (no hidden tabs).
    ImGui::DockBuilderDockWindow(windowName(EditorWindow::Stats), rightMiddle);
    ImGui::DockBuilderDockWindow(windowName(EditorWindow::Log), rightBottom);
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

void placeWindow(EditorWindow) {}

int editorWindowFlags() { return 0; }

#else

void beginLayout(LayoutState& state) {
    // Tiled windows are re-placed every frame, so a reset has nothing to restore.
    state.resetRequested = false;
}

void placeWindow(EditorWindow window) {
    ImGuiViewport const* viewport = ImGui::GetMainViewport();
    TileRect const r = tiledRect(window, {viewport->WorkPos.x, viewport->WorkPos.y},
                                 {viewport->WorkSize.x, viewport->WorkSize.y});
    ImGui::SetNextWindowPos(ImVec2(r.pos.x, r.pos.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(r.size.x, r.size.y), ImGuiCond_Always);
}

int editorWindowFlags() {
    return ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
           ImGuiWindowFlags_NoBringToFrontOnFocus;
}

#endif

}  // namespace gbl::ui
