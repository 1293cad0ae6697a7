// Tool toggles, header counts, region and diff statistics, and the viewers' keys.
#include "panels/viewer_tools.h"

#include "model/colormap.h"
#include "panels/gui_util.h"
#include "panels/wrapped_text.h"

#include <algorithm>
#include <bit>
#include <cstdio>

namespace gbl::ui {

namespace {
// The colormap combo: wide enough for the longest map name beside the combo's arrow.
float mapComboWidth() {
    return ImGui::CalcTextSize("viridis").x + ImGui::GetFrameHeight() + ImGui::GetStyle().FramePadding.x * 2.0f;
}
}  // namespace

float viewerCellMinWidth() {
    ImGuiStyle const& style = ImGui::GetStyle();
    auto button = [&](char const* label) { return ImGui::CalcTextSize(label).x + style.FramePadding.x * 2.0f; };
    float const toolbar = ImGui::CalcTextSize("specular").x + style.ItemSpacing.x * 2.0f + button("R") + button("G") +
                          button("B") + button("A") + 6.0f + button("...");
    // 4 px more keeps the last button clear of the column border.
    return toolbar + style.CellPadding.x * 2.0f + 4.0f;
}

void sameLineIfRoom(float w, float right) {
    if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + w <= right) ImGui::SameLine();
}

void viewerHeaderCounts(ViewerState const& v, ViewerData const& d) {
    if (d.frame < 0 || v.overlays == 0) return;
    // The cell's right edge: the cursor is at the start of the line after the viewer's name.
    float const right = ImGui::GetCursorScreenPos().x + ImGui::GetContentRegionAvail().x;
    auto count = [&](ImU32 colour, char const* label, long n) {
        char text[40];
        std::snprintf(text, sizeof text, "%s %ld", label, n);
        // Wrap instead of running out of a narrow cell.
        if (ImGui::GetItemRectMax().x + 8.0f + ImGui::CalcTextSize(text).x <= right) ImGui::SameLine();
        ImGui::PushStyleColor(ImGuiCol_Text, n > 0 ? colour : IM_COL32(140, 140, 140, 255));
        ImGui::TextUnformatted(text);
        ImGui::PopStyleColor();
    };
    count(kNaNColour, "NaN", d.stats.nanPixels);
    count(kInfColour, "Inf", d.stats.infPixels);
    count(kNegativeColour, "neg", d.stats.negativePixels);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("pixels with a shown channel NaN / +-Inf / below 0 (counted on the CPU read-back)");
}

void viewerToolsRow(ViewerState& v, ViewerData const& d) {
    // Items wrap to a new line instead of running out of a narrow cell.
    float const right = ImGui::GetCursorScreenPos().x + ImGui::GetContentRegionAvail().x;
    auto next = [&](char const* label) {
        float const w = ImGui::CalcTextSize(label).x + ImGui::GetStyle().FramePadding.x * 2.0f;
        if (ImGui::GetItemRectMax().x + 2.0f + w <= right) ImGui::SameLine(0, 2);
    };
    auto toggle = [](char const* label, bool on) {
        ImGui::PushStyleColor(ImGuiCol_Button, on ? IM_COL32(70, 110, 170, 255) : IM_COL32(50, 50, 55, 255));
        bool const clicked = ImGui::SmallButton(label);
        ImGui::PopStyleColor();
        return clicked;
    };
    if (toggle("Hist", v.showHistogram)) v.showHistogram = !v.showHistogram;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("histogram of the shown channels with the black/white points");
    float const mapWidth = mapComboWidth();
    if (ImGui::GetItemRectMax().x + 2.0f + mapWidth <= right) ImGui::SameLine(0, 2);
    int map = int(v.colormap);
    ImGui::SetNextItemWidth(mapWidth);
    char const* maps[] = {kColormapNames[0].data(), kColormapNames[1].data(), kColormapNames[2].data()};
    if (ImGui::Combo("##map", &map, maps, 3)) v.colormap = Colormap(map);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("colormap, used when one channel is shown");
    next("Ovl");
    if (toggle("Ovl", v.overlays != 0)) ImGui::OpenPopup("overlays");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("overlays: NaN, Inf, negative, clipping");
    if (ImGui::BeginPopup("overlays")) {
        ImGui::CheckboxFlags("NaN (magenta)", &v.overlays, kOverlayNaN);
        ImGui::CheckboxFlags("Inf (green)", &v.overlays, kOverlayInf);
        ImGui::CheckboxFlags("negative (cyan)", &v.overlays, kOverlayNegative);
        ImGui::CheckboxFlags("clipping (blue below black, red above white)", &v.overlays, kOverlayClip);
        ImGui::EndPopup();
    }
    next("Pin");
    if (ImGui::SmallButton("Pin")) v.pinRequested = true;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(d.pinned ? "pinned at frame %ld; click to pin the current frame instead"
                                   : "keep this frame's values to compare against",
                          d.pinnedFrame);
    next("Diff");
    ImGui::BeginDisabled(!d.pinned);
    if (toggle("Diff", v.showDiff)) v.showDiff = !v.showDiff;
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("show |current - pinned| as a heat map (black: equal; magenta: NaN/Inf)");
}

void viewerRegionAndDiff(ViewerState& v, ViewerData const& d) {
    static constexpr char const* kChannel[4] = {"R", "G", "B", "A"};
    // Narrow cells: buttons go below what does not leave them room, statistics wrap.
    float const right = ImGui::GetCursorScreenPos().x + ImGui::GetContentRegionAvail().x;
    auto buttonWidth = [](char const* label) {
        return ImGui::CalcTextSize(label, nullptr, true).x + ImGui::GetStyle().FramePadding.x * 2.0f;
    };
    // The region rows: "no region" and room for the statistics without a region, the statistics
    // with one. While a Shift+drag is
    // on, only the region's line is drawn, padded to the rows' height when the drag began, so
    // the image below keeps its place and the region matches the texels under the mouse.
    ImGui::BeginGroup();
    float const top = ImGui::GetCursorScreenPos().y;
    if (v.regionDragStart && v.region) {
        PixelRect const r = *v.region;
        ImGui::TextDisabled("region %d,%d %dx%d", r.min.x, r.min.y, r.max.x - r.min.x, r.max.y - r.min.y);
        // The padding starts one item spacing below the line.
        float const pad = v.regionRowsHeight - (ImGui::GetItemRectMax().y - top) - ImGui::GetStyle().ItemSpacing.y;
        if (pad > 0.0f) ImGui::Dummy(ImVec2(1.0f, pad));
    } else if (v.region) {
        PixelRect const r = *v.region;
        ImGui::TextDisabled("region %d,%d %dx%d", r.min.x, r.min.y, r.max.x - r.min.x, r.max.y - r.min.y);
        sameLineIfRoom(buttonWidth("Fit to region"), right);
        if (ImGui::SmallButton("Fit to region")) v.regionFitRequested = true;
        sameLineIfRoom(buttonWidth("x##region"), right);
        if (ImGui::SmallButton("x##region")) v.region.reset();
        if (d.frame >= 0 && v.region) {
            unsigned const mask = viewerStatsMask(v);
            for (int c = 0; c < 4; ++c) {
                if (!(mask & (1u << c))) continue;
                ChannelStats const& s = d.regionStats.channel[std::size_t(c)];
                wrappedText("%s min %.4g max %.4g mean %.4g NaN %ld", v.kind == ViewerKind::Depth ? "d" : kChannel[c],
                            s.min, s.max, s.mean, s.nan);
            }
        }
        v.regionRowsHeight = ImGui::GetItemRectMax().y - top;
    } else {
        ImGui::TextDisabled("no region");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Shift+drag in the image: statistics of a region");
        // Room for the statistics rows a region brings (one line each where they do not wrap), so
        // the image keeps its place and size when the drag ends.
        int const rows = d.frame >= 0 ? std::popcount(viewerStatsMask(v)) : 0;
        if (rows > 0)
            ImGui::Dummy(
                ImVec2(1.0f, ImGui::GetTextLineHeightWithSpacing() * float(rows) - ImGui::GetStyle().ItemSpacing.y));
        v.regionRowsHeight = ImGui::GetItemRectMax().y - top;
    }
    ImGui::EndGroup();
    if (v.showDiff && d.pinned) {
        if (!d.diff.comparable) {
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.6f, 0.3f, 1));
            wrappedText("pinned image has another size; pin again");
            ImGui::PopStyleColor();
            return;
        }
        ImGui::SetNextItemWidth(std::min(ImGui::GetFontSize() * 5.0f, ImGui::GetContentRegionAvail().x));
        ImGui::DragFloat("##threshold", &v.diffThreshold, 0.001f, 0.0f, 1e6f, "thr %.4g", ImGuiSliderFlags_AlwaysClamp);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("pixels whose difference is above this are counted; 0 = any change");
        sameLineIfRoom(ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize("rel").x,
                       right);
        bool rel = v.diffMode == DiffMode::Relative;
        if (ImGui::Checkbox("rel", &rel)) v.diffMode = rel ? DiffMode::Relative : DiffMode::Absolute;
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("relative: |a - b| / |pinned|");
        wrappedText("max %.4g at %d,%d  mean %.3g", d.diff.max, d.diff.maxAt.x, d.diff.maxAt.y, d.diff.mean);
        wrappedText("over %ld of %ld  NaN/Inf %ld", d.diff.overThreshold, d.diff.pixels, d.diff.nanPixels);
    }
}

void viewerKeys(GBufferPanelState& panel) {
    if (!ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows) || ImGui::GetIO().WantTextInput) return;
    if (panel.activeViewer < 0 || panel.activeViewer > 4) return;  // the viewport's texel: Shift+right-click only
    ViewerState& v = panel.viewers[std::size_t(std::clamp(panel.activeViewer, 0, 4))];
    if (ImGui::GetIO().KeyCtrl && letterPressed('G')) {
        panel.goToOpen = true;
        panel.goToInput = v.picked.value_or(glm::ivec2(0));
    }
    if (!v.picked || v.imageSize.x <= 0) return;
    glm::ivec2 step{0};
    if (arrowPressed(-1, 0)) step.x -= 1;
    if (arrowPressed(1, 0)) step.x += 1;
    if (arrowPressed(0, -1)) step.y -= 1;
    if (arrowPressed(0, 1)) step.y += 1;
    if (step != glm::ivec2(0)) v.picked = glm::clamp(*v.picked + step, glm::ivec2(0), v.imageSize - 1);
}

}  // namespace gbl::ui
