// Pixel inspector window.
#include "panels/panel_pixel_inspector.h"

#include "panels/gui_compat.h"
#include "panels/layout.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gbl::ui {

namespace {
void row(char const* label, glm::vec4 v, int n = 4) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(label);
    for (int i = 0; i < 4; ++i) {
        ImGui::TableNextColumn();
        if (i < n) ImGui::Text("%.4g", v[i]);
    }
}
}  // namespace

void drawPixelInspectorPanel(PixelInspectorState& state) {
    state.selectLight = -1;
    placeWindow(EditorWindow::PixelInspector);
    if (ImGui::Begin(windowName(EditorWindow::PixelInspector), nullptr, editorWindowFlags())) {
        ImGui::Checkbox("Lock (L)", &state.locked);
        ImGui::SameLine();
        if (state.pixel)
            ImGui::Text("pixel (%d, %d) from %s", state.pixel->x, state.pixel->y, state.source.c_str());
        else
            ImGui::TextDisabled("hover the viewport or a viewer");

        if (state.sample) {
            PixelSample const& s = *state.sample;
            if (!s.covered) ImGui::TextDisabled("background: no geometry at this pixel");
            ImGuiTableFlags const flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchProp;
            if (ImGui::BeginTable("values", 5, flags)) {
                ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, ImGui::GetFontSize() * 6.5f);
                for (char const* c : {"x / r", "y / g", "z / b", "w / a"}) ImGui::TableSetupColumn(c);
                ImGui::TableHeadersRow();
                row("position", s.position);
                // Background depth is the far plane: a position rebuilt from it means nothing.
                if (s.covered) row("from depth", glm::vec4(s.reconstructedPosition, 0.0f), 3);
                row("normal", s.normal);
                row("albedo,spec", s.albedoSpec);
                row("depth", glm::vec4(s.depth, 0, 0, 0), 1);
                row("lighting", s.lighting);
                ImGui::EndTable();
            }
            if (s.covered) {
                float const err = glm::length(glm::vec3(s.position) - s.reconstructedPosition);
                ImGui::Text("rebuilt from depth is %.3g units off", err);
            }
        }

        separatorText("Lights at this pixel");
        if (!state.breakdown) {
            ImGui::TextDisabled("%s", state.breakdownNote.empty() ? "no pixel" : state.breakdownNote.c_str());
        } else {
            PixelBreakdown const& b = *state.breakdown;
            ImGui::Text("%d of %d lights reach it", int(b.lights.size()), b.lightsTested);
            // Fixed columns with horizontal scrolling: six numbers per light never fit a side column.
            ImGuiTableFlags const flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_ScrollX |
                                          ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingFixedFit;
            float const height = std::max(ImGui::GetContentRegionAvail().y - ImGui::GetTextLineHeightWithSpacing() * 3.2f, 60.0f);
            if (ImGui::BeginTable("lights", 5, flags, ImVec2(0, height))) {
                ImGui::TableSetupScrollFreeze(0, 1);
                for (char const* c : {"light", "dist", "atten", "diffuse", "specular"}) ImGui::TableSetupColumn(c);
                ImGui::TableHeadersRow();
                ImGuiListClipper clipper;
                clipper.Begin(int(b.lights.size()));
                while (clipper.Step()) {
                    for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
                        gbl::LightContribution const& c = b.lights[std::size_t(i)];
                        ImGui::TableNextRow();
                        ImGui::TableNextColumn();
                        char label[16];
                        std::snprintf(label, sizeof label, "%d", c.lightIndex);
                        if (ImGui::Selectable(label, false, ImGuiSelectableFlags_SpanAllColumns)) state.selectLight = c.lightIndex;
                        ImGui::TableNextColumn();
                        ImGui::Text("%.3f", c.distance);
                        ImGui::TableNextColumn();
                        ImGui::Text("%.4f", c.attenuation);
                        ImGui::TableNextColumn();
                        ImGui::Text("%.3f %.3f %.3f", c.diffuse.r, c.diffuse.g, c.diffuse.b);
                        ImGui::TableNextColumn();
                        ImGui::Text("%.3f %.3f %.3f", c.specular.r, c.specular.g, c.specular.b);
                    }
                }
                ImGui::EndTable();
            }
            ImGui::Text("ambient %.4f %.4f %.4f", b.ambient.r, b.ambient.g, b.ambient.b);
            glm::vec3 const stored = state.sample ? glm::vec3(state.sample->lighting) : glm::vec3(0.0f);
            ImGui::Text("sum     %.4f %.4f %.4f", b.total.r, b.total.g, b.total.b);
            ImGui::Text("stored  %.4f %.4f %.4f", stored.r, stored.g, stored.b);
        }
    }
    ImGui::End();
}

}  // namespace gbl::ui
