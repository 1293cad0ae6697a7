// G-buffer window: viewers drawn with the renderer's view pass, shown with nearest-neighbour
// texels so zooming in shows exact stored pixels.
#include "panels/panel_gbuffer.h"

#include "model/msaa_views.h"
#include "model/viewer_fields.h"
#include "model/viewer_tools.h"
#include "panels/gui_util.h"
#include "panels/item_rect.h"
#include "panels/layout.h"
#include "panels/viewer_tools.h"

#include <imgui.h>
#include <imgui_internal.h>  // the window's last width (FindWindowByName)

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gbl::ui {

namespace {

// Draws the image with zoom and pan inside the remaining cell area; returns the hovered texel.
// Shift+drag draws the statistics region, right-click picks the magnifier's texel; `marker` is a
// texel hovered in another viewer (Sync), outlined here.
std::optional<glm::ivec2> viewerImage(ViewerState& v, unsigned texture, glm::ivec2 imageSize, bool& clicked,
                                      std::optional<glm::ivec2> marker, std::optional<glm::ivec2> locked,
                                      glm::vec4& fittedRect) {
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
    glm::vec2 const fitted(float(imageSize.x) * fit, float(imageSize.y) * fit);
    fittedRect = glm::vec4(cellCentre.x - fitted.x * 0.5f, cellCentre.y - fitted.y * 0.5f, fitted.x, fitted.y);
    auto imageMin = [&] { return ImVec2(cellCentre.x - v.center.x * full.x, cellCentre.y - v.center.y * full.y); };

    if (hovered && io.MouseWheel != 0.0f) {
        // Zoom about the point under the mouse, so it stays where it is.
        ImVec2 const m = io.MousePos;
        ImVec2 const before = imageMin();
        glm::vec2 const p((m.x - before.x) / full.x, (m.y - before.y) / full.y);
        static ViewerField const& zoomField = *findViewerField("zoom");  // its range is the sessions' too
        float const newZoom = std::clamp(v.zoom * std::pow(1.25f, io.MouseWheel), zoomField.min, zoomField.max);
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
    if (locked) markLockedPixel(dl, p0, fullNow, imageSize, *locked);
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

// Labels over the image's top-left corner: the zoom, DIFF while the diff is shown and the
// NaN/Inf/negative counts while overlays are on. Drawn over the image, so they never take its
// height.
void imageLabels(ViewerState const& v, ViewerData const& d, ImVec2 origin, float width) {
    char text[128];
    int n = 0;
    text[0] = '\0';
    auto add = [&](char const* fmt, auto... args) {
        if (n < 0 || n >= int(sizeof text)) return;
        if (n > 0) n += std::snprintf(text + n, sizeof text - std::size_t(n), "  ");
        if (n < int(sizeof text)) n += std::snprintf(text + n, sizeof text - std::size_t(n), fmt, args...);
    };
    if (v.zoom > 1.0f) add("x%.1f", double(v.zoom));
    if (v.showDiff && d.pinned) add("DIFF");
    if (d.frame >= 0 && v.overlays != 0)
        add("NaN %ld  Inf %ld  neg %ld", d.stats.nanPixels, d.stats.infPixels, d.stats.negativePixels);
    if (n <= 0) return;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    float const wrap = std::max(width - 8.0f, 40.0f);
    ImVec2 const size = ImGui::CalcTextSize(text, nullptr, false, wrap);
    ImVec2 const p(origin.x + 4.0f, origin.y + 3.0f);
    dl->AddRectFilled(ImVec2(p.x - 2, p.y - 1), ImVec2(p.x + size.x + 2, p.y + size.y + 1), IM_COL32(0, 0, 0, 170));
    ImU32 const colour = v.showDiff && d.pinned ? IM_COL32(255, 180, 50, 255) : IM_COL32(235, 235, 235, 255);
    dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), p, colour, text, nullptr, wrap);
}

// Over a viewer's image (x, y, width, height) while the mode writes no G-buffer: why it is empty.
void drawNoGBufferNote(glm::vec4 rect, std::string const& note) {
    if (rect.z <= 0.0f || rect.w <= 0.0f) return;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    ImVec2 const min(rect.x, rect.y), max(rect.x + rect.z, rect.y + rect.w);
    dl->AddRectFilled(min, max, IM_COL32(24, 24, 28, 255));
    char const* text = note.c_str();
    float const wrap = std::max(60.0f, rect.z - 12.0f);
    ImVec2 const size = ImGui::CalcTextSize(text, nullptr, false, wrap);
    ImVec2 const p((min.x + max.x - size.x) * 0.5f, (min.y + max.y - size.y) * 0.5f);
    dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), p, IM_COL32(235, 235, 235, 255), text, nullptr, wrap);
}

// Along the bottom of a viewer's image (x, y, width, height): where its values come from when not
// from the layout's G-buffer (prepass's thin one).
void sourceCaption(glm::vec4 rect, std::string const& caption) {
    if (rect.z <= 0.0f || rect.w <= 0.0f) return;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    float const wrap = std::max(40.0f, rect.z - 8.0f);
    ImVec2 const size = ImGui::CalcTextSize(caption.c_str(), nullptr, false, wrap);
    ImVec2 const p(rect.x + 4.0f, rect.y + rect.w - size.y - 3.0f);
    dl->AddRectFilled(ImVec2(p.x - 2, p.y - 1), ImVec2(p.x + size.x + 2, p.y + size.y + 1), IM_COL32(0, 0, 0, 170));
    dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), p, IM_COL32(150, 220, 255, 255), caption.c_str(), nullptr,
                wrap);
}

// The options of the whole G-buffer window, at the foot of every viewer's popover.
void windowOptions(GBufferPanelState& state) {
    separatorText("all viewers");
    ImGui::Checkbox("Redraw all", &state.refreshEveryFrame);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "redraw every viewer every frame; off: one viewer is redrawn per frame in turn (cheaper\n"
            "on slow GL), and a viewer whose settings change is redrawn at once");
    ImGui::Checkbox("Sync zoom/pan", &state.syncViews);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("link zoom and pan of all viewers: the same texel under the cursor in each");
    ImGui::Checkbox("Magnifier", &state.showMagnifier);
    ImGui::TextDisabled(
        "click: show in viewport  drag: pan\nwheel: zoom  double-click: reset\nShift+drag: statistics region\n"
        "right-click: pick texel (magnifier)\narrow keys: step the picked texel\nCtrl+G: go to pixel");
}

// The viewer's one-line toolbar: its name, the channel toggles, Fit, and "..." for the popover
// with everything else (range, kind options, histogram, colormap, overlays, pin, diff, region).
// One line whatever is on, so the image below never changes size.
void viewerToolbar(GBufferPanelState& state, std::size_t i) {
    ViewerState& v = state.viewers[i];
    ViewerData const& d = state.data[i];
    float const right = rowRightEdge();
    float const more = ImGui::CalcTextSize("...").x + ImGui::GetStyle().FramePadding.x * 2.0f;
    ImGui::TextUnformatted(v.kind == ViewerKind::Depth && v.showStencil ? "stencil" : kViewerNames[i].data());
    ImGui::SameLine();
    viewerChannelToggles(v);
    // msaa: the sample shown, on the toolbar itself (the depth viewer shows the resolved depth).
    float const sampleWidth = ImGui::CalcTextSize("sample 0").x + ImGui::GetFrameHeight() + 8.0f;
    if (state.msaaSamples > 0 && viewerSampleSlot(v.kind) &&
        ImGui::GetItemRectMax().x + 4.0f + sampleWidth + more <= right) {
        ImGui::SameLine(0, 4);
        viewerSampleSelector(v.sample, state.msaaSamples, true, "toolbar-sample");
        state.sampleRects[i] = lastItemRect();
    } else {
        state.sampleRects[i] = glm::vec4(0.0f);
    }
    float const fit = ImGui::CalcTextSize("Fit").x + ImGui::GetStyle().FramePadding.x * 2.0f;
    if (viewerRemaps(v.kind) && ImGui::GetItemRectMax().x + 2.0f + fit + 4.0f + more <= right) {
        ImGui::SameLine(0, 2);
        if (ImGui::SmallButton("Fit")) v.fitRequested = true;
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "fit the range to the data now, min..max (auto-fit, in \"...\", takes the 1-99 %% range)");
    }
    ImGui::SameLine();
    // Right-aligned in the cell, where it is found in every viewer.
    ImVec2 const at = ImGui::GetCursorScreenPos();
    ImGui::SetCursorScreenPos(ImVec2(std::max(at.x, right - more), at.y));
    if (ImGui::SmallButton("...##details")) ImGui::OpenPopup("viewer-details");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("range, %s, histogram, colormap, overlays, pin and diff, region statistics",
                          v.kind == ViewerKind::Depth ? "linear/stencil" : "display");
    float const width = ImGui::GetFontSize() * 21.0f;
    ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, 1e6f));
    if (ImGui::BeginPopup("viewer-details")) {
        viewerControls(v, true, state.msaaSamples);
        viewerToolsRow(v, d);
        viewerHistogram(v, d);
        viewerRegionAndDiff(v, d);
        windowOptions(state);
        ImGui::EndPopup();
    }
}

}  // namespace

void drawGBufferPanel(GBufferPanelState& state, std::array<unsigned, 5> const& textures, glm::ivec2 imageSize,
                      std::optional<glm::ivec2> lockedPixel) {
    std::optional<glm::ivec2> const previousHover = state.hoverPixel;
    state.hoverPixel.reset();
    state.showInViewport.reset();
    state.imageRects.fill(glm::vec4(0.0f));
    // Little padding above and below: the strip's height is the images'. The images fill the
    // window exactly, so it never scrolls (a scrollbar coming and going would resize them).
    // Five cells narrower than viewerCellMinWidth would cut their toolbars off: the window then
    // scrolls sideways instead (a large UI scale), its scrollbar always shown, below the images
    // (a scrolling table's own scrollbar would lie over their bottom rows). Whether it is that
    // narrow is known from its last frame.
    float const width = viewerCellMinWidth() * float(state.viewers.size());
    ImGuiWindow const* last = ImGui::FindWindowByName(windowName(EditorWindow::GBuffer));
    bool const narrow = last && last->ContentRegionRect.GetWidth() < width;
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(ImGui::GetStyle().WindowPadding.x, 3.0f));
    state.visible =
        ImGui::Begin(windowName(EditorWindow::GBuffer), nullptr,
                     ImGuiWindowFlags_NoScrollWithMouse |
                         (narrow ? ImGuiWindowFlags_HorizontalScrollbar | ImGuiWindowFlags_AlwaysHorizontalScrollbar
                                 : ImGuiWindowFlags_NoScrollbar));
    ImGui::PopStyleVar();
    if (state.visible) {
        ImVec2 avail = ImGui::GetContentRegionAvail();
        if (narrow) avail.x = width;
        bool const table =
            ImGui::BeginTable("viewers", 5, ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchSame, avail);
        if (table) {
            for (std::size_t i = 0; i < state.viewers.size(); ++i) ImGui::TableSetupColumn(kViewerNames[i].data());
            ImGui::TableNextRow(ImGuiTableRowFlags_None);
            for (std::size_t i = 0; i < state.viewers.size(); ++i) {
                ViewerState& v = state.viewers[i];
                ImGui::TableNextColumn();
                ImGui::PushID(int(i));
                viewerToolbar(state, i);
                v.imageSize = imageSize;
                bool clicked = false;
                float const zoomBefore = v.zoom;
                glm::vec2 const centerBefore = v.center;
                std::optional<glm::ivec2> const marker = state.syncViews ? previousHover : std::nullopt;
                ImVec2 const imageOrigin = ImGui::GetCursorScreenPos();
                float const cellWidth = ImGui::GetContentRegionAvail().x;
                if (i == 0) state.imageArea = {cellWidth, ImGui::GetContentRegionAvail().y};
                if (auto texel =
                        viewerImage(v, textures[i], imageSize, clicked, marker, lockedPixel, state.imageRects[i])) {
                    state.hoverPixel = texel;
                    if (!state.showMagnifier || !v.picked) state.activeViewer = int(i);
                }
                if (!state.noGBuffer[i].empty()) drawNoGBufferNote(state.imageRects[i], state.noGBuffer[i]);
                imageLabels(v, state.data[i], imageOrigin, cellWidth);
                if (!state.source[i].empty()) sourceCaption(state.imageRects[i], state.source[i]);
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
