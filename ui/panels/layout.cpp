// Default dock layout (DockBuilder) and the tiled fallback for ImGui builds without docking.
#include "panels/layout.h"

#include "panels/fonts.h"
#include "panels/gui_compat.h"
#include "panels/panel_frame.h"

#include <imgui.h>
#ifdef IMGUI_HAS_DOCK
#include <imgui_internal.h>
#endif

#include <cmath>
#include <cstdio>
#include <optional>

namespace gbl::ui {

#ifdef IMGUI_HAS_DOCK

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

void placeWindow(EditorWindow) {}

void drawSplitHandles(LayoutState&) {}

void placeFrameWindow() {
    // Docked beside the strip by the default layout; a layout restored from an older imgui.ini has
    // no place for it, so it floats at a size that shows a few passes until docked.
    ImGuiViewport const* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowSize(ImVec2(viewport->WorkSize.x * 0.8f, viewport->WorkSize.y * kViewerStrip),
                             ImGuiCond_FirstUseEver);
}

int editorWindowFlags() {
    return 0;
}

#else

namespace {
// The boundaries this frame places windows by (beginLayout copies them from the LayoutState).
std::optional<LayoutSplits> tiledSplits;

glm::vec2 workPos() {
    ImGuiViewport const* viewport = ImGui::GetMainViewport();
    return {viewport->WorkPos.x, viewport->WorkPos.y};
}
glm::vec2 workSize() {
    ImGuiViewport const* viewport = ImGui::GetMainViewport();
    return {viewport->WorkSize.x, viewport->WorkSize.y};
}
}  // namespace

void beginLayout(LayoutState& state) {
    // Tiled windows are re-placed every frame: a reset puts the boundaries back to the defaults.
    if (state.resetRequested && state.splits) {
        state.splits.reset();
        ImGui::MarkIniSettingsDirty();
    }
    state.resetRequested = false;
    tiledSplits = state.splits;
}

void drawSplitHandles(LayoutState& state) {
    auto const handles = splitHandles(workPos(), workSize(), uiScaleFactor(), state.splits);
    ImGuiWindowFlags const flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;
    for (std::size_t i = 0; i < handles.size(); ++i) {
        TileRect const& r = handles[i];
        if (r.size.x < 1.0f || r.size.y < 1.0f) continue;  // a minimised or zero-sized window has no edges
        bool const across = r.size.y > r.size.x;           // a column boundary: dragged left and right
        char name[32];
        std::snprintf(name, sizeof name, "##split%zu", i);
        ImGui::SetNextWindowPos(ImVec2(r.pos.x, r.pos.y), ImGuiCond_Always);
        ImGui::SetNextWindowSize(ImVec2(r.size.x, r.size.y), ImGuiCond_Always);
        ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0.0f, 0.0f));
        ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1.0f, 1.0f));
        ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
        ImGui::Begin(name, nullptr, flags);
        ImGui::InvisibleButton("handle", ImVec2(r.size.x, r.size.y));
        bool const hovered = ImGui::IsItemHovered(), active = ImGui::IsItemActive();
        if (hovered || active) {
            ImGui::SetMouseCursor(across ? ImGuiMouseCursor_ResizeEW : ImGuiMouseCursor_ResizeNS);
            ImVec2 const a(r.pos.x, r.pos.y), b(r.pos.x + r.size.x, r.pos.y + r.size.y);
            ImGui::GetForegroundDrawList()->AddRectFilled(
                a, b, ImGui::GetColorU32(active ? ImGuiCol_SeparatorActive : ImGuiCol_SeparatorHovered));
        }
        if (active && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f)) {
            ImVec2 const mouse = ImGui::GetIO().MousePos;
            state.splits =
                dragSplit(state.splits, Split(i), {mouse.x, mouse.y}, workPos(), workSize(), uiScaleFactor());
            state.draggingSplit = int(i);
        }
        if (ImGui::IsItemDeactivated() && state.draggingSplit == int(i)) {
            state.draggingSplit = -1;
            ImGui::MarkIniSettingsDirty();  // imgui.ini keeps the boundaries with the UI scale
        }
        ImGui::End();
        ImGui::PopStyleVar(3);
    }
    state.handles = handles;
}

void placeWindow(EditorWindow window) {
    TileRect const r = tiledRect(window, workPos(), workSize(), uiScaleFactor(), tiledSplits);
    ImGui::SetNextWindowPos(ImVec2(r.pos.x, r.pos.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(r.size.x, r.size.y), ImGuiCond_Always);
}

void placeFrameWindow() {
    placeWindow(EditorWindow::GBuffer);  // over the strip: full width for the diagram
}

int editorWindowFlags() {
    return ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
           ImGuiWindowFlags_NoBringToFrontOnFocus;
}

#endif

}  // namespace gbl::ui
