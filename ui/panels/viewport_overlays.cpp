// What the viewport draws over its image (viewport_overlays.h).
#include "panels/viewport_overlays.h"

#include "core/cluster_math.h"
#include "core/heat_scale.h"
#include "model/colormap.h"
#include "model/lesson_claims.h"
#include "panels/gui_util.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gbl::ui {

// Labels for the heat legend that shaders/view.frag draws into the image itself (heatLegend:
// kHeatBins swatches of kHeatSwatchTexels from texel x 8, rows 6..22 from the bottom). Only the
// words are drawn here, in a box just above that bar: the quantity on one line, each swatch's
// lowest count centred over it on the next, so there is one legend and it is labelled.
void labelHeatLegend(ImVec2 imageMin, ImVec2 imageMax, glm::ivec2 textureSize, DebugView view, LightingMode mode) {
    if (textureSize.x < 64 || textureSize.y < 64) return;  // the shader draws no legend either
    float const sx = (imageMax.x - imageMin.x) / float(textureSize.x);
    float const sy = (imageMax.y - imageMin.y) / float(textureSize.y);
    int const w = std::max(std::min(textureSize.x - 16, kHeatSwatchTexels * kHeatBins) / kHeatBins, 1);
    float const x0 = imageMin.x + 8.0f * sx, swatch = float(w) * sx, x1 = x0 + swatch * float(kHeatBins);
    float const barTop = imageMax.y - 23.0f * sy, line = ImGui::GetTextLineHeight();
    std::string title(heatQuantity(view, mode));
    if (view == DebugView::Heatmap) title += "; lower half: none of them lit";
    // Numbers over their swatches when the widest fits; else one line, left to right.
    bool const fits = ImGui::CalcTextSize(heatBinLabel(kHeatBins - 1).c_str()).x + 2.0f <= swatch;
    std::string numbers;
    if (!fits)
        for (int k = 0; k < kHeatBins; ++k) numbers += (k ? ", " : "") + heatBinLabel(k);
    float const top = barTop - 2.0f * line - 4.0f;
    float const right =
        std::max({x1, x0 + ImGui::CalcTextSize(title.c_str()).x, x0 + ImGui::CalcTextSize(numbers.c_str()).x});
    ImDrawList* dl = ImGui::GetWindowDrawList();
    ImU32 const text = IM_COL32(235, 235, 235, 255);
    dl->AddRectFilled(ImVec2(x0 - 3.0f, top - 1.0f), ImVec2(right + 3.0f, barTop), IM_COL32(0, 0, 0, 170));
    dl->AddText(ImVec2(x0, top), text, title.c_str());
    if (!fits) {
        dl->AddText(ImVec2(x0, top + line), text, numbers.c_str());
        return;
    }
    for (int k = 0; k < kHeatBins; ++k) {
        std::string const label = heatBinLabel(k);
        float const cx = x0 + (float(k) + 0.5f) * swatch;
        dl->AddText(ImVec2(std::round(cx - 0.5f * ImGui::CalcTextSize(label.c_str()).x), top + line), text,
                    label.c_str());
    }
}

float heatLegendHeight(ImVec2 imageMin, ImVec2 imageMax, glm::ivec2 textureSize) {
    if (textureSize.x < 64 || textureSize.y < 64) return 0.0f;
    float const sy = (imageMax.y - imageMin.y) / float(textureSize.y);
    return 23.0f * sy + 2.0f * ImGui::GetTextLineHeight() + 6.0f;
}

// Labels for the depth-slice legend (shaders/view.frag sliceLegend: kClusterSlices swatches of
// kSliceSwatchTexels from texel x 8, rows 6..22 from the bottom): a box above it listing each
// slice's view-depth range beside its colour, in columns of 8.
void labelSliceLegend(ImVec2 imageMin, ImVec2 imageMax, glm::ivec2 textureSize, glm::vec2 clip) {
    if (textureSize.x < 64 || textureSize.y < 64) return;  // the shader draws no legend either
    float const sy = (imageMax.y - imageMin.y) / float(textureSize.y);
    float const barTop = imageMax.y - 23.0f * sy;
    float const line = ImGui::GetTextLineHeight(), swatch = line * 0.8f;
    float const column = ImGui::CalcTextSize("23: 100.00 - 100.00 ").x + swatch + 6.0f;
    int const rows = 8, columns = (kClusterSlices + rows - 1) / rows;
    ImVec2 const p0(imageMin.x + 8.0f, barTop - 6.0f - float(rows + 1) * line);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(ImVec2(p0.x - 3.0f, p0.y - 2.0f), ImVec2(p0.x + float(columns) * column, barTop - 3.0f),
                      IM_COL32(0, 0, 0, 170));
    dl->AddText(p0, IM_COL32(235, 235, 235, 255), "depth slice: view depth range");
    for (int k = 0; k < kClusterSlices; ++k) {
        ImVec2 const p(p0.x + float(k / rows) * column, p0.y + float(k % rows + 1) * line);
        glm::vec3 const c = clusterSliceColor(k) * 255.0f;
        dl->AddRectFilled(ImVec2(p.x, p.y + 0.1f * line), ImVec2(p.x + swatch, p.y + 0.9f * line),
                          IM_COL32(int(c.r), int(c.g), int(c.b), 255));
        char text[64];
        std::snprintf(text, sizeof text, "%d: %.2f - %.2f", k, clusterSliceNear(k, clip.x, clip.y),
                      clusterSliceNear(k + 1, clip.x, clip.y));
        dl->AddText(ImVec2(p.x + swatch + 4.0f, p.y), IM_COL32(235, 235, 235, 255), text);
    }
}

// Text with a dark box behind it, so it reads over any frame.
void boxedText(ImVec2 p, std::string const& text) {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    ImVec2 const size = ImGui::CalcTextSize(text.c_str());
    dl->AddRectFilled(ImVec2(p.x - 3, p.y - 1), ImVec2(p.x + size.x + 3, p.y + size.y + 1), IM_COL32(0, 0, 0, 180));
    dl->AddText(p, IM_COL32(240, 240, 240, 255), text.c_str());
}

// One side's GPU ms per pass, as much as fits in `width` pixels: every pass, else the passes of
// 1 ms or more, else the total alone (the Stats window lists every pass).
std::string passLine(char const* side, std::vector<PassTiming> const& passes, double total, float width, bool timed) {
    // A browser without timer queries cannot time a pass (gl/gpu_timer.h).
    if (!timed) return std::string(side) + ": passes not timed in this browser";
    char buf[64];
    std::snprintf(buf, sizeof buf, ", total %.1f", total);
    std::string const tail = buf;
    std::string out;
    for (double const least : {0.0, 1.0}) {
        out = std::string(side) + " GPU ms:";
        for (PassTiming const& p : passes) {
            if (p.gpuMs < least) continue;
            std::snprintf(buf, sizeof buf, " %s %.1f", p.name.c_str(), p.gpuMs);
            out += buf;
        }
        out += tail;
        if (ImGui::CalcTextSize(out.c_str()).x <= width) return out;
    }
    std::snprintf(buf, sizeof buf, "%s GPU ms: total %.1f", side, total);
    return buf;
}

std::string sideLabel(char const* side, PipelineSettings const& s) {
    std::string out = std::string(side) + ": " + std::string(enumName(kLightingModeNames, s.mode));
    if (s.mode == LightingMode::Volumes) {  // appended: "/" + string trips GCC 12 -O3's -Wrestrict
        out += '/';
        out += enumName(kCullModeNames, s.cull);
    }
    return out;
}

// The divider between A (left) and B (right), dragged with the left button. Submitted before the
// image's own button so that it, not the camera drag, takes the press.
void abDivider(AbState& ab, ImVec2 origin, ImVec2 avail) {
    float const x = origin.x + ab.divider * avail.x;
    float const grab = 10.0f;
    ImGui::SetCursorScreenPos(ImVec2(x - grab * 0.5f, origin.y));
    ImGui::InvisibleButton("ab-divider", ImVec2(grab, avail.y));
    if (ImGui::IsItemHovered() || ImGui::IsItemActive()) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
    if (ImGui::IsItemActive()) ab.divider = std::clamp((ImGui::GetIO().MousePos.x - origin.x) / avail.x, 0.02f, 0.98f);
    ImGui::SetCursorScreenPos(origin);
}

// B over the right of the divider, the line, the two labels and each side's pass times.
void drawAbSplit(ViewportTeaching const& v, PipelineSettings const& a, ImVec2 origin, ImVec2 avail, float bottomInset) {
    AbState const& ab = v.ab;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    float const x = origin.x + ab.divider * avail.x;
    ImVec2 const end(origin.x + avail.x, origin.y + avail.y);
    if (v.textureB != 0)
        dl->AddImage(toImTexture(v.textureB), ImVec2(x, origin.y), end, ImVec2(ab.divider, 1), ImVec2(1, 0));
    dl->AddLine(ImVec2(x, origin.y), ImVec2(x, end.y), IM_COL32(0, 0, 0, 220), 4.0f);
    dl->AddLine(ImVec2(x, origin.y), ImVec2(x, end.y), IM_COL32(255, 230, 80, 255), 2.0f);
    dl->AddCircleFilled(ImVec2(x, origin.y + avail.y * 0.5f), 7.0f, IM_COL32(255, 230, 80, 255));
    float const line = ImGui::GetTextLineHeightWithSpacing();
    boxedText(ImVec2(origin.x + 8, origin.y + 6), sideLabel("A", a));
    std::string const b = sideLabel("B", v.settingsB);
    boxedText(ImVec2(end.x - ImGui::CalcTextSize(b.c_str()).x - 8, origin.y + 6), b);
    boxedText(ImVec2(origin.x + 8, origin.y + 6 + line), "B differs in: " + describeAb(a, v.settingsB));
    float const bottom = end.y - bottomInset;
    if (ab.evaluations)
        boxedText(ImVec2(origin.x + 8, bottom - 3 * line - 4),
                  evaluationsLine(ab.evaluations->first, ab.evaluations->second));
    boxedText(ImVec2(origin.x + 8, bottom - 2 * line - 4),
              passLine("A", ab.passesA, ab.gpuMsA, avail.x - 16, ab.passesTimed));
    boxedText(ImVec2(origin.x + 8, bottom - line - 4),
              passLine("B", ab.passesB, ab.gpuMsB, avail.x - 16, ab.passesTimed));
}

// The |A - B| heat map's legend (turbo from 0 to its scale) and the diff's numbers.
void drawAbDiff(ViewportTeaching const& v, PipelineSettings const& a, ImVec2 origin, ImVec2 avail) {
    AbState const& ab = v.ab;
    bool const angle = ab.metric == AbMetric::NormalAngle;
    DiffStats const& d = angle ? ab.normalDiff : ab.pin.diff;
    float const threshold = angle ? ab.angleThreshold : ab.threshold;
    char const* unit = angle ? " deg" : "";
    ImDrawList* dl = ImGui::GetWindowDrawList();
    float const line = ImGui::GetTextLineHeightWithSpacing();
    float const scale = ab.heatToThreshold ? threshold : d.max;
    char const* what = ab.diffMode == DiffMode::Relative ? "|A-B|/|B|" : "|A-B|";
    char buf[256];
    if (angle)
        std::snprintf(buf, sizeof buf, "angle between A's and B's decoded normals, degrees (magenta: one side only)");
    else
        std::snprintf(buf, sizeof buf, "%s of the lit HDR frame, largest RGB channel (magenta: NaN/Inf)", what);
    boxedText(ImVec2(origin.x + 8, origin.y + 6), buf);
    boxedText(ImVec2(origin.x + 8, origin.y + 6 + line), "A vs B: " + describeAb(a, v.settingsB));
    if (!d.comparable) return;
    std::snprintf(buf, sizeof buf, "max %.4g%s at %d,%d   mean %.4g   %ld of %ld px over %.3g   NaN/Inf px %ld", d.max,
                  unit, d.maxAt.x, d.maxAt.y, d.mean, d.overThreshold, d.pixels, threshold, d.nanPixels);
    boxedText(ImVec2(origin.x + 8, origin.y + 6 + 2 * line), buf);
    // Legend: a turbo ramp 0 .. scale, the same ramp diffHeatmap paints.
    float const w = std::min(256.0f, avail.x - 40.0f), h = 12.0f;
    ImVec2 const p0(origin.x + 12, origin.y + avail.y - 3 * line - h - 10);
    dl->AddRectFilled(ImVec2(p0.x - 4, p0.y - 4), ImVec2(p0.x + w + 4, p0.y + h + line + 2), IM_COL32(0, 0, 0, 180));
    for (int i = 0; i < 64; ++i) {
        glm::vec3 const c = colormap(Colormap::Turbo, (float(i) + 0.5f) / 64.0f);
        dl->AddRectFilled(ImVec2(p0.x + w * float(i) / 64.0f, p0.y), ImVec2(p0.x + w * float(i + 1) / 64.0f, p0.y + h),
                          IM_COL32(int(c.r * 255), int(c.g * 255), int(c.b * 255), 255));
    }
    dl->AddText(ImVec2(p0.x, p0.y + h + 1), IM_COL32(240, 240, 240, 255), "0");
    std::snprintf(buf, sizeof buf, "%.3g%s%s", scale, unit, ab.heatToThreshold ? " (threshold)" : " (max)");
    dl->AddText(ImVec2(p0.x + w - ImGui::CalcTextSize(buf).x, p0.y + h + 1), IM_COL32(240, 240, 240, 255), buf);
    boxedText(ImVec2(origin.x + 8, origin.y + avail.y - 2 * line - 4),
              passLine("A", ab.passesA, ab.gpuMsA, avail.x - 16, ab.passesTimed));
    boxedText(ImVec2(origin.x + 8, origin.y + avail.y - line - 4),
              passLine("B", ab.passesB, ab.gpuMsB, avail.x - 16, ab.passesTimed));
}

}  // namespace gbl::ui
