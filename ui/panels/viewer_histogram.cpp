// Histogram of a viewer's shown channels with draggable black/white points, and the legend.
#include "panels/viewer_tools.h"

#include "model/colormap.h"
#include "panels/wrapped_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gbl::ui {

namespace {

ImU32 toImColour(glm::vec3 c) {
    return IM_COL32(int(c.r * 255.0f + 0.5f), int(c.g * 255.0f + 0.5f), int(c.b * 255.0f + 0.5f), 255);
}

// Legend under the histogram: the colormap from the black to the white point, ticks in data units.
void legend(ViewerState const& v, ImVec2 p0, float width, float lo, float hi) {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    float const h = ImGui::GetFontSize() * 0.6f;
    auto xOf = [&](float value) { return p0.x + (value - lo) / (hi - lo) * width; };
    float const x0 = xOf(v.rangeMin), x1 = xOf(v.rangeMax);
    Colormap const map = v.channelMask == 1 || v.channelMask == 2 || v.channelMask == 4 || v.channelMask == 8 ||
                                 v.kind == ViewerKind::Depth || v.kind == ViewerKind::Specular
                             ? v.colormap
                             : Colormap::Grey;
    int const steps = 48;
    for (int i = 0; i < steps; ++i) {
        float const a = x0 + (x1 - x0) * float(i) / steps, b = x0 + (x1 - x0) * float(i + 1) / steps;
        dl->AddRectFilled(ImVec2(a, p0.y), ImVec2(b + 0.5f, p0.y + h),
                          toImColour(colormap(map, (float(i) + 0.5f) / steps)));
    }
    float const textY = p0.y + h + 1.0f;
    float lastRight = -1e9f;
    for (LegendTick const& t : legendTicks(v.rangeMin, v.rangeMax, 4)) {
        float const x = x0 + t.position * (x1 - x0);
        dl->AddLine(ImVec2(x, p0.y), ImVec2(x, p0.y + h + 2.0f), IM_COL32(255, 255, 255, 200));
        char label[32];
        std::snprintf(label, sizeof label, "%g", double(t.value));
        float const w = ImGui::CalcTextSize(label).x;
        float const left = std::clamp(x - w * 0.5f, p0.x, p0.x + width - w);
        if (left < lastRight + 4.0f) continue;  // no overlapping labels in a narrow cell
        dl->AddText(ImVec2(left, textY), IM_COL32(200, 200, 200, 255), label);
        lastRight = left + w;
    }
    ImGui::Dummy(ImVec2(width, h + ImGui::GetFontSize() + 2.0f));
}

}  // namespace

void viewerHistogram(ViewerState& v, ViewerData const& d) {
    if (!v.showHistogram) return;
    bool const remaps = viewerRemaps(v.kind);
    if (remaps) {
        float const right = ImGui::GetCursorScreenPos().x + ImGui::GetContentRegionAvail().x;
        if (ImGui::SmallButton("Fit min/max")) v.fitRequested = true;
        // Beside it when the cell has room, else below: never cut at the cell's edge.
        float const w = ImGui::CalcTextSize("Fit 1-99 %").x + ImGui::GetStyle().FramePadding.x * 2.0f;
        if (ImGui::GetItemRectMax().x + 2.0f + w <= right) ImGui::SameLine(0, 2);
        if (ImGui::SmallButton("Fit 1-99 %")) v.percentileFitRequested = true;
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "black/white points at the 1st and 99th percentile of the finite values: NaN, Inf\n"
                "and the 1 %% outliers at each end do not stretch the range");
    }
    if (d.frame < 0 || d.histogram.bins.empty()) {
        ImGui::TextDisabled("reading values...");
        return;
    }
    float const width = ImGui::GetContentRegionAvail().x;
    float const height = ImGui::GetFontSize() * 3.5f;
    if (width < 16.0f) return;
    ImVec2 const p0 = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("histogram", ImVec2(width, height));
    bool const hovered = ImGui::IsItemHovered(), active = ImGui::IsItemActive();
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(p0, ImVec2(p0.x + width, p0.y + height), IM_COL32(20, 20, 24, 255));
    Histogram const& h = d.histogram;
    float const lo = h.lo, hi = h.hi;
    long const top = std::max(h.maxBin(), 1L);
    float const binW = width / float(h.bins.size());
    for (std::size_t i = 0; i < h.bins.size(); ++i) {
        if (h.bins[i] == 0) continue;
        // Square root of the count: one bin of background or a flat floor would flatten the rest.
        float const f = std::sqrt(float(h.bins[i]) / float(top));
        float const x = p0.x + float(i) * binW;
        dl->AddRectFilled(ImVec2(x, p0.y + height * (1.0f - f)), ImVec2(x + std::max(binW - 0.5f, 1.0f), p0.y + height),
                          IM_COL32(170, 170, 180, 255));
    }
    auto xOf = [&](float value) { return p0.x + (value - lo) / (hi - lo) * width; };
    auto valueAt = [&](float x) { return lo + (x - p0.x) / width * (hi - lo); };
    if (remaps) {
        float const xb = xOf(v.rangeMin), xw = xOf(v.rangeMax);
        dl->AddLine(ImVec2(xb, p0.y), ImVec2(xb, p0.y + height), IM_COL32(80, 140, 255, 255), 2.0f);
        dl->AddLine(ImVec2(xw, p0.y), ImVec2(xw, p0.y + height), IM_COL32(255, 90, 80, 255), 2.0f);
        ImGuiIO const& io = ImGui::GetIO();
        if (ImGui::IsItemActivated())
            v.histogramDrag = std::abs(io.MousePos.x - xb) <= std::abs(io.MousePos.x - xw) ? 0 : 1;
        if (!active) v.histogramDrag = -1;
        if (active && v.histogramDrag >= 0) {
            float const value = valueAt(std::clamp(io.MousePos.x, p0.x, p0.x + width));
            float const gap = (hi - lo) * 1e-4f;
            if (v.histogramDrag == 0)
                v.rangeMin = std::min(value, v.rangeMax - gap);
            else
                v.rangeMax = std::max(value, v.rangeMin + gap);
            v.autoFit = false;  // a dragged point stays where it was put
        }
        if (hovered)
            ImGui::SetTooltip(
                "%.4g\ndrag: move the nearer point (blue: black, red: white)\nbelow black %ld  above white %ld",
                double(valueAt(io.MousePos.x)), d.clip.below, d.clip.above);
    } else if (hovered) {
        ImGui::SetTooltip("%.4g", double(valueAt(ImGui::GetIO().MousePos.x)));
    }
    // Wrapped: a narrow cell breaks the line instead of cutting it at its edge.
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    wrappedText("%.4g .. %.4g   mean %.4g", d.stats.shown.min, d.stats.shown.max, d.stats.shown.mean);
    ImGui::PopStyleColor();
    if (remaps) legend(v, ImGui::GetCursorScreenPos(), width, lo, hi);
}

}  // namespace gbl::ui
