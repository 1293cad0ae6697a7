// G-buffer window: viewers drawn with the renderer's view pass, shown with nearest-neighbour
// texels so zooming in shows exact stored pixels.
#include "panels/panel_gbuffer.h"

#include "model/viewer_tools.h"
#include "panels/gui_compat.h"
#include "panels/layout.h"
#include "panels/viewer_tools.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace gbl::ui {

namespace {

// Draws the image with zoom and pan inside the remaining cell area; returns the hovered texel.
// Shift+drag draws the statistics region, right-click picks the magnifier's texel; `marker` is a
// texel hovered in another viewer (Sync), outlined here.
std::optional<glm::ivec2> viewerImage(ViewerState& v, unsigned texture, glm::ivec2 imageSize, bool& clicked,
                                      std::optional<glm::ivec2> marker) {
    ImVec2 const avail = ImGui::GetContentRegionAvail();
    ImVec2 const origin = ImGui::GetCursorScreenPos();
    if (avail.x < 4.0f || avail.y < 4.0f || imageSize.x <= 0 || imageSize.y <= 0) return std::nullopt;
    ImGui::InvisibleButton("image", avail, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
    bool const hovered = ImGui::IsItemHovered();
    ImGuiIO const& io = ImGui::GetIO();

    // Screen size of the whole image at zoom 1: fit the cell, keep the aspect.
    float const fit = std::min(avail.x / float(imageSize.x), avail.y / float(imageSize.y));
    ImVec2 const full(float(imageSize.x) * fit * v.zoom, float(imageSize.y) * fit * v.zoom);
    ImVec2 const cellCentre(origin.x + avail.x * 0.5f, origin.y + avail.y * 0.5f);
    auto imageMin = [&] { return ImVec2(cellCentre.x - v.center.x * full.x, cellCentre.y - v.center.y * full.y); };

    if (hovered && io.MouseWheel != 0.0f) {
        // Zoom about the point under the mouse, so it stays where it is.
        ImVec2 const m = io.MousePos;
        ImVec2 const before = imageMin();
        glm::vec2 const p((m.x - before.x) / full.x, (m.y - before.y) / full.y);
        float const newZoom = std::clamp(v.zoom * std::pow(1.25f, io.MouseWheel), 1.0f, 256.0f);
        float const k = newZoom / v.zoom;
        v.zoom = newZoom;
        glm::vec2 const mouseFromCentre(m.x - cellCentre.x, m.y - cellCentre.y);
        v.center = p - mouseFromCentre / (glm::vec2(full.x, full.y) * k);
    }
    auto texelAt = [&](ImVec2 m) {
        ImVec2 const p = imageMin();
        glm::vec2 const uv((m.x - p.x) / full.x, (m.y - p.y) / full.y);
        return glm::clamp(glm::ivec2(glm::floor(uv * glm::vec2(imageSize))), glm::ivec2(0), imageSize - 1);
    };
    if (ImGui::IsItemActivated() && io.KeyShift) v.regionDragStart = texelAt(io.MousePos);
    if (!ImGui::IsItemActive()) v.regionDragStart.reset();
    if (v.regionDragStart)
        v.region = rectFromCorners(*v.regionDragStart, texelAt(io.MousePos));
    else if (ImGui::IsItemActive() && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f))
        v.center -= glm::vec2(io.MouseDelta.x / full.x, io.MouseDelta.y / full.y);
    if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Right)) v.picked = texelAt(io.MousePos);
    if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
        v.zoom = 1.0f;
        v.center = glm::vec2(0.5f);
    }
    if (v.zoom <= 1.0f) v.center = glm::vec2(0.5f);
    v.center = glm::clamp(v.center, glm::vec2(0.0f), glm::vec2(1.0f));

    ImVec2 const fullNow(float(imageSize.x) * fit * v.zoom, float(imageSize.y) * fit * v.zoom);
    ImVec2 const p0 = imageMin();
    ImVec2 const p1(p0.x + fullNow.x, p0.y + fullNow.y);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->PushClipRect(origin, ImVec2(origin.x + avail.x, origin.y + avail.y), true);
    dl->AddRectFilled(origin, ImVec2(origin.x + avail.x, origin.y + avail.y), IM_COL32(12, 12, 14, 255));
    if (texture != 0) dl->AddImage(toImTexture(texture), p0, p1, ImVec2(0, 1), ImVec2(1, 0));
    if (v.region) outlineTexels(dl, p0, fullNow, imageSize, v.region->min, v.region->max, IM_COL32(255, 255, 255, 230));
    if (v.picked) outlineTexels(dl, p0, fullNow, imageSize, *v.picked, *v.picked + 1, IM_COL32(255, 160, 0, 255));
    if (marker) outlineTexels(dl, p0, fullNow, imageSize, *marker, *marker + 1, IM_COL32(0, 255, 255, 255));
    dl->PopClipRect();

    if (hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
        io.MouseDragMaxDistanceSqr[ImGuiMouseButton_Left] < 9.0f)
        clicked = true;
    if (!hovered) return std::nullopt;
    float const u = (io.MousePos.x - p0.x) / fullNow.x, t = (io.MousePos.y - p0.y) / fullNow.y;
    if (u < 0.0f || u >= 1.0f || t < 0.0f || t >= 1.0f) return std::nullopt;
    glm::ivec2 const texel(int(u * float(imageSize.x)), int(t * float(imageSize.y)));
    if (v.zoom >= 8.0f) {
        // Outline the texel under the mouse once texels are big enough to see.
        float const tw = fullNow.x / float(imageSize.x), th = fullNow.y / float(imageSize.y);
        ImVec2 const a(p0.x + float(texel.x) * tw, p0.y + float(texel.y) * th);
        dl->PushClipRect(origin, ImVec2(origin.x + avail.x, origin.y + avail.y), true);
        dl->AddRect(a, ImVec2(a.x + tw, a.y + th), IM_COL32(255, 255, 0, 255));
        dl->PopClipRect();
    }
    return texel;
}

}  // namespace

void drawGBufferPanel(GBufferPanelState& state, std::array<unsigned, 5> const& textures, glm::ivec2 imageSize) {
    std::optional<glm::ivec2> const previousHover = state.hoverPixel;
    state.hoverPixel.reset();
    state.showInViewport.reset();
    placeWindow(EditorWindow::GBuffer);
    // Five cells narrower than viewerCellMinWidth would cut their controls off: the strip then
    // scrolls sideways instead (1280x720 with the Lessons window beside it).
    state.visible = ImGui::Begin(windowName(EditorWindow::GBuffer), nullptr,
                                 editorWindowFlags() | ImGuiWindowFlags_HorizontalScrollbar);
    if (state.visible) {
        float const right = ImGui::GetCursorScreenPos().x + ImGui::GetContentRegionAvail().x;
        auto checkWidth = [](char const* label) {
            return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label).x;
        };
        ImGui::Checkbox("Redraw all", &state.refreshEveryFrame);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "redraw every viewer every frame; off: one viewer is redrawn per frame in turn (cheaper\n"
                "on slow GL), and a viewer whose settings change is redrawn at once");
        sameLineIfRoom(checkWidth("Sync zoom/pan"), right);
        ImGui::Checkbox("Sync zoom/pan", &state.syncViews);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("link zoom and pan of all viewers: the same texel under the cursor in each");
        sameLineIfRoom(checkWidth("Magnifier"), right);
        ImGui::Checkbox("Magnifier", &state.showMagnifier);
        sameLineIfRoom(ImGui::CalcTextSize("(?)").x, right);
        ImGui::TextDisabled("(?)");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "click: show in viewport  drag: pan  wheel: zoom  double-click: reset\n"
                "Shift+drag: statistics region  right-click: pick texel (magnifier)\n"
                "arrow keys: step the picked texel  Ctrl+G: go to pixel");
        ImVec2 const avail = ImGui::GetContentRegionAvail();
        float const width = std::max(avail.x, viewerCellMinWidth() * float(state.viewers.size()));
        if (ImGui::BeginTable("viewers", 5, ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchSame,
                              ImVec2(width, avail.y))) {
            for (std::size_t i = 0; i < state.viewers.size(); ++i) ImGui::TableSetupColumn(kViewerNames[i].data());
            ImGui::TableNextRow(ImGuiTableRowFlags_None, ImGui::GetContentRegionAvail().y);
            for (std::size_t i = 0; i < state.viewers.size(); ++i) {
                ViewerState& v = state.viewers[i];
                ImGui::TableNextColumn();
                ImGui::PushID(int(i));
                ImGui::TextUnformatted(v.kind == ViewerKind::Depth && v.showStencil ? "stencil"
                                                                                    : kViewerNames[i].data());
                if (v.zoom > 1.0f) {
                    ImGui::SameLine();
                    ImGui::TextDisabled("x%.1f", v.zoom);
                }
                if (v.showDiff && state.data[i].pinned) {
                    ImGui::SameLine();
                    ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.2f, 1.0f), "DIFF");
                }
                viewerHeaderCounts(v, state.data[i]);
                viewerControls(v, true);
                viewerToolsRow(v, state.data[i]);
                viewerHistogram(v, state.data[i]);
                viewerRegionAndDiff(v, state.data[i]);
                v.imageSize = imageSize;
                bool clicked = false;
                float const zoomBefore = v.zoom;
                glm::vec2 const centerBefore = v.center;
                std::optional<glm::ivec2> const marker = state.syncViews ? previousHover : std::nullopt;
                if (auto texel = viewerImage(v, textures[i], imageSize, clicked, marker)) {
                    state.hoverPixel = texel;
                    if (!state.showMagnifier || !v.picked) state.activeViewer = int(i);
                }
                if (ImGui::IsItemClicked(ImGuiMouseButton_Right) || clicked) state.activeViewer = int(i);
                if (clicked) state.showInViewport = viewerDebugView(v);
                if (state.syncViews && (v.zoom != zoomBefore || v.center != centerBefore)) syncViewers(state, i);
                ImGui::PopID();
            }
            ImGui::EndTable();
        }
        viewerKeys(state);
    }
    ImGui::End();
}

}  // namespace gbl::ui
