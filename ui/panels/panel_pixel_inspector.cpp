// Pixel inspector window.
#include "panels/panel_pixel_inspector.h"

#include "core/gbuffer_layout.h"
#include "core/heat_scale.h"
#include "model/pixel_breakdown.h"
#include "model/viewer_tools.h"
#include "panels/gui_util.h"
#include "panels/layout.h"
#include "panels/viewer_tools.h"
#include "panels/wrapped_text.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace gbl::ui {

namespace {
// The widest texts "%.4g" writes for a float: sign, 4 digits, point and a two-digit exponent
// ("-1.234e-05"), or the same length in fixed notation ("-0.0001234").
constexpr char const* kWidestValues[] = {"-8.888e-08", "-0.0008888", "-8.888e+38"};

float valueColumnWidth() {
    float w = 0.0f;
    for (char const* text : kWidestValues) w = std::max(w, ImGui::CalcTextSize(text).x);
    return w;
}

void row(char const* label, glm::vec4 v, int n = 4) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(label);
    for (int i = 0; i < 4; ++i) {
        ImGui::TableNextColumn();
        if (i < n) ImGui::Text("%.4g", v[i]);
    }
}
// msaa (issue 47): the pixel's samples as the lighting decodes them, every one or the one selected.
void msaaSamplesSection(PixelInspectorState& state) {
    int const n = int(state.msaaSamples.size());
    if (n == 0) return;
    separatorText("MSAA samples");
    viewerSampleSelector(state.msaaSample, n, true, "inspector-sample");
    ImGui::SameLine();
    ImGui::TextDisabled("%d samples, decoded as the lighting reads them", n);
    ImGuiTableFlags const flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                  ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX;
    // A scrolling table needs its height: a header and four rows per listed sample, as the values table.
    int const rows = 1 + 4 * (state.msaaSample >= 0 ? 1 : n);
    float const rowHeight = ImGui::GetTextLineHeight() + ImGui::GetStyle().CellPadding.y * 2.0f;
    ImVec2 const size(0.0f, float(rows) * rowHeight + ImGui::GetStyle().ScrollbarSize + 2.0f);
    if (!ImGui::BeginTable("samples", 5, flags, size)) return;
    ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("s7 albedo,spec").x);
    float const w = valueColumnWidth();
    for (char const* c : {"x / r", "y / g", "z / b", "w / a"})
        ImGui::TableSetupColumn(c, ImGuiTableColumnFlags_WidthFixed, w);
    ImGui::TableHeadersRow();
    for (int k = 0; k < n; ++k) {
        if (state.msaaSample >= 0 && k != state.msaaSample) continue;
        MsaaPixelSample const& s = state.msaaSamples[std::size_t(k)];
        std::string const tag = "s" + std::to_string(k) + " ";
        row((tag + "position").c_str(), s.position);
        row((tag + "normal").c_str(), s.normal);
        row((tag + "albedo,spec").c_str(), s.albedoSpec);
        row((tag + "emissive,ao").c_str(), s.emissiveAo);
    }
    ImGui::EndTable();
}
}  // namespace

void drawPixelInspectorPanel(PixelInspectorState& state) {
    state.selectLight = -1;
    if (ImGui::Begin(windowName(EditorWindow::PixelInspector), nullptr)) {
        ImGui::Checkbox("Lock (L)", &state.locked);
        ImGui::SameLine();
        if (state.pixel)
            ImGui::Text("pixel (%d, %d) from %s", state.pixel->x, state.pixel->y, state.source.c_str());
        else
            ImGui::TextDisabled("hover the viewport or a viewer");

        if (state.sample) {
            PixelSample const& s = *state.sample;
            if (!s.covered) ImGui::TextDisabled("background: no geometry at this pixel");
            // Columns as wide as the widest value the font draws, so no digit is ever cut; a narrow
            // window scrolls the table sideways instead.
            ImGuiTableFlags const flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                          ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX;
            int const rows = s.covered ? 7 : 6;  // header, values, and the rebuilt position if drawn
            float const rowHeight = ImGui::GetTextLineHeight() + ImGui::GetStyle().CellPadding.y * 2.0f;
            ImVec2 const size(0.0f, float(rows) * rowHeight + ImGui::GetStyle().ScrollbarSize + 2.0f);
            if (ImGui::BeginTable("values", 5, flags, size)) {
                ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("albedo,spec").x);
                float const w = valueColumnWidth();
                for (char const* c : {"x / r", "y / g", "z / b", "w / a"})
                    ImGui::TableSetupColumn(c, ImGuiTableColumnFlags_WidthFixed, w);
                ImGui::TableHeadersRow();
                row("position", s.position);
                // Background depth is the far plane: a position rebuilt from it means nothing.
                if (s.covered) row("from depth", glm::vec4(s.reconstructedPosition, 0.0f), 3);
                row("normal", s.normal);
                // prepass's thin G-buffer: no albedo or emission; w holds the specular exponent
                row(s.thinGBuffer ? "-,exponent" : "albedo,spec", s.albedoSpec);
                if (!s.thinGBuffer) row("emissive,ao", s.emissiveAo);
                row(s.thinGBuffer ? "lit depth" : "depth", glm::vec4(s.depth, 0, 0, 0), 1);
                row("lighting", s.lighting);
                ImGui::EndTable();
            }
            // The depth as stored (DEPTH32F) with its raw bits, as the magnifier shows them.
            wrappedText("depth stored %s", storedFloatText(s.depth).c_str());
            ImGui::Text("stencil %u", s.stencil);
            // The count a heat map shows as a colour bin, exactly (core/heat_scale.h).
            if (s.coverageView && *s.coverageView == state.settings.view) {
                std::string const quantity(heatQuantity(*s.coverageView, s.coverageMode));
                std::string const bin = heatBinRange(heatBin(s.coverage.x));
                wrappedText("%s: %.0f here (colour of %s), %.0f of them lit it", quantity.c_str(), double(s.coverage.x),
                            bin.c_str(), double(s.coverage.y));
            }
            // A layout without the emissive_ao attachment shows emissive 0 and ao 1: say why.
            if (std::string const note = layoutOmissionNote(layoutDesc(state.settings.layout)); !note.empty())
                wrappedText("emissive,ao not stored: %s", note.c_str());
            if (s.covered) {
                float const err = glm::length(glm::vec3(s.position) - s.reconstructedPosition);
                ImGui::Text("rebuilt from depth is %.3g units off", err);
            }
        }

        msaaSamplesSection(state);
        separatorText("Lights at this pixel");
        if (!state.breakdown) {
            ImGui::TextDisabled("%s", state.breakdownNote.empty() ? "no pixel" : state.breakdownNote.c_str());
        } else {
            PixelBreakdown const& b = *state.breakdown;
            ImGui::Text("%d of %d lights reach it", int(b.lights.size()), b.lightsTested);
            if (!b.verdicts.empty()) {
                ImGui::SameLine();
                ImGui::Checkbox("every light", &state.everyLight);
            }
            // Totals first, so the table below takes whatever height is left and nothing is cut off.
            ImGui::Text("ambient %.4f %.4f %.4f", b.ambient.r, b.ambient.g, b.ambient.b);
            glm::vec3 const stored = state.sample ? glm::vec3(state.sample->lighting) : glm::vec3(0.0f);
            ImGui::Text("sum     %.4f %.4f %.4f", b.total.r, b.total.g, b.total.b);
            ImGui::Text("stored  %.4f %.4f %.4f", stored.r, stored.g, stored.b);
            if (state.theirs) {
                glm::vec3 const t = *state.theirs;
                ImGui::Text("theirs  %.4f %.4f %.4f", t.r, t.g, t.b);
                if (ImGui::IsItemHovered())
                    ImGui::SetTooltip(
                        "the open G-buffer's own lit image here (its manifest's \"lit\"); off from stored by\n"
                        "%.4f %.4f %.4f. Close to sum: their G-buffer and lights explain their image under this\n"
                        "lighting; far from it: compare the lights below with their shader's",
                        t.r - stored.r, t.g - stored.g, t.b - stored.b);
            }
            if (!b.verdicts.empty()) {
                // What this mode should have stored: ambient plus what each evaluated light added.
                glm::vec3 evaluated = b.ambient;
                for (LightVerdict const& v : b.verdicts) evaluated += v.added;
                ImGui::Text("by mode %.4f %.4f %.4f", evaluated.r, evaluated.g, evaluated.b);
            }
            if (state.sample) {
                // The flag: stored and summed differ by more than fp16 storage explains.
                ValueCheck const check = checkStoredValue(stored, b, state.settings);
                if (!check.agrees) {
                    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.35f, 1.0f));
                    wrappedText("stored != sum of the lights: off by %.4f (fp16 allows %.4f). Likely: %s", check.error,
                                check.allowed, check.cause.c_str());
                    ImGui::PopStyleColor();
                }
            }
            // Rows: the verdicts (every light, why it was or was not evaluated) when present,
            // brightest first; otherwise the lights that reach the pixel.
            std::vector<int> rows;
            std::vector<int> contributionOf(b.verdicts.size(), -1);
            for (std::size_t i = 0; i < b.lights.size(); ++i)
                if (std::size_t(b.lights[i].lightIndex) < contributionOf.size())
                    contributionOf[std::size_t(b.lights[i].lightIndex)] = int(i);
            if (b.verdicts.empty()) {
                for (std::size_t i = 0; i < b.lights.size(); ++i) rows.push_back(int(i));
            } else {
                for (std::size_t i = 0; i < b.verdicts.size(); ++i)
                    if (state.everyLight || b.verdicts[i].withinRadius) rows.push_back(int(i));
                auto lum = [&](int i) {
                    glm::vec3 a = b.verdicts[std::size_t(i)].added;
                    return a.r + a.g + a.b;
                };
                std::stable_sort(rows.begin(), rows.end(), [&](int x, int y) { return lum(x) > lum(y); });
            }
            // Fixed columns with horizontal scrolling: six numbers per light never fit a side column.
            ImGuiTableFlags const flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                          ImGuiTableFlags_ScrollX | ImGuiTableFlags_ScrollY |
                                          ImGuiTableFlags_SizingFixedFit;
            float const height = std::max(ImGui::GetContentRegionAvail().y - ImGui::GetStyle().ItemSpacing.y, 60.0f);
            if (ImGui::BeginTable("lights", 8, flags, ImVec2(0, height))) {
                ImGui::TableSetupScrollFreeze(0, 1);
                for (char const* c : {"light", "evaluated?", "added", "dist", "atten", "diffuse", "specular", "why"})
                    ImGui::TableSetupColumn(c);
                ImGui::TableHeadersRow();
                ImGuiListClipper clipper;
                clipper.Begin(int(rows.size()));
                while (clipper.Step()) {
                    for (int r = clipper.DisplayStart; r < clipper.DisplayEnd; ++r) {
                        int const row = rows[std::size_t(r)];
                        LightVerdict const* v = b.verdicts.empty() ? nullptr : &b.verdicts[std::size_t(row)];
                        int const ci = v ? contributionOf[std::size_t(row)] : row;
                        gbl::LightContribution const* c = ci >= 0 ? &b.lights[std::size_t(ci)] : nullptr;
                        int const index = v ? v->lightIndex : c->lightIndex;
                        ImGui::TableNextRow();
                        ImGui::TableNextColumn();
                        char label[16];
                        std::snprintf(label, sizeof label, "%d", index);
                        if (ImGui::Selectable(label, false, ImGuiSelectableFlags_SpanAllColumns))
                            state.selectLight = index;
                        ImGui::TableNextColumn();
                        if (!v)
                            ImGui::TextDisabled("-");
                        else if (v->evaluations > 1)
                            ImGui::Text("yes x%d", v->evaluations);
                        else
                            ImGui::TextUnformatted(v->evaluated ? "yes" : "no");
                        ImGui::TableNextColumn();
                        glm::vec3 const added = v ? v->added : c->total();
                        ImGui::Text("%.3f %.3f %.3f", added.r, added.g, added.b);
                        ImGui::TableNextColumn();
                        if (c) ImGui::Text("%.3f", c->distance);
                        ImGui::TableNextColumn();
                        // Spots: distance attenuation times the cone factor; directional: 1.
                        if (c && c->cone < 1.0f)
                            ImGui::Text("%.4f x cone %.3f", c->attenuation, c->cone);
                        else if (c)
                            ImGui::Text("%.4f", c->attenuation);
                        ImGui::TableNextColumn();
                        if (c) ImGui::Text("%.3f %.3f %.3f", c->diffuse.r, c->diffuse.g, c->diffuse.b);
                        ImGui::TableNextColumn();
                        if (c) ImGui::Text("%.3f %.3f %.3f", c->specular.r, c->specular.g, c->specular.b);
                        ImGui::TableNextColumn();
                        if (v) ImGui::TextUnformatted(v->why.c_str());
                    }
                }
                ImGui::EndTable();
            }
        }
    }
    ImGui::End();
}

}  // namespace gbl::ui
