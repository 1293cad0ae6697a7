// The viewport's MSAA toggles and pictures (viewport_msaa.h).
#include "panels/viewport_msaa.h"

#include "core/heat_scale.h"
#include "panels/gui_util.h"
#include "panels/item_rect.h"

#include <algorithm>
#include <cstdio>

namespace gbl::ui {

void msaaViewsRow(MsaaViewState& m) {
    if (m.samples <= 0) {
        m.complexRect = m.heatRect = glm::vec4(0.0f);
        return;
    }
    ImGui::Checkbox("Complex", &m.complexOverlay);
    m.complexRect = lastItemRect();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "msaa: the complex pixels in magenta, whose samples differ in coverage, position, normal or\n"
            "albedo beyond the thresholds (docs/msaa.md); the edges strategy lights these per sample");
    ImGui::SameLine();
    ImGui::Checkbox("Samples", &m.samplesHeat);
    m.heatRect = lastItemRect();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("msaa: how many distinct surfaces each pixel's %d samples hold, on the heat scale",
                          m.samples);
    ImGui::SameLine();
    char text[64];
    if (m.complexShare)
        std::snprintf(text, sizeof text, "complex %.1f %%", *m.complexShare * 100.0);
    else
        std::snprintf(text, sizeof text, "complex: tick a view");
    ImGui::TextUnformatted(text);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("share of the frame's pixels that are complex (msaa %dx)", m.samples);
    ImGui::SameLine();
}

void drawMsaaViews(MsaaViewState const& m, ImVec2 origin, ImVec2 end) {
    if (m.samples <= 0) return;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    // The pictures are rows top to bottom, uploaded bottom-up like a frame: flipped as the frame is.
    if (m.heatTexture != 0) dl->AddImage(toImTexture(m.heatTexture), origin, end, ImVec2(0, 1), ImVec2(1, 0));
    if (m.overlayTexture != 0) dl->AddImage(toImTexture(m.overlayTexture), origin, end, ImVec2(0, 1), ImVec2(1, 0));
    if (m.heatTexture == 0) return;
    // Legend: one swatch per heat bin the sample counts can reach (1 .. samples), labelled with its counts.
    float const line = ImGui::GetTextLineHeight(), swatch = line * 0.9f;
    ImVec2 p(origin.x + 8.0f, end.y - 8.0f - line * 2.0f);
    int const last = heatBin(float(m.samples));
    float row = 0.0f;
    for (int b = 1; b <= last; ++b) row += swatch + ImGui::CalcTextSize(heatBinRange(b).c_str()).x + 12.0f;
    float const width = std::max(ImGui::CalcTextSize("distinct samples per pixel").x, row);
    dl->AddRectFilled(ImVec2(p.x - 4.0f, p.y - 3.0f), ImVec2(p.x + width + 8.0f, end.y - 4.0f), IM_COL32(0, 0, 0, 180));
    dl->AddText(p, IM_COL32(235, 235, 235, 255), "distinct samples per pixel");
    p.y += line;
    for (int b = 1; b <= last; ++b) {
        glm::vec3 const c = heatBinColor(b) * 255.0f;
        dl->AddRectFilled(ImVec2(p.x, p.y + 0.1f * line), ImVec2(p.x + swatch, p.y + 0.1f * line + swatch),
                          IM_COL32(int(c.r), int(c.g), int(c.b), 255));
        std::string const label = heatBinRange(b);
        dl->AddText(ImVec2(p.x + swatch + 3.0f, p.y), IM_COL32(235, 235, 235, 255), label.c_str());
        p.x += swatch + ImGui::CalcTextSize(label.c_str()).x + 12.0f;
    }
}

}  // namespace gbl::ui
