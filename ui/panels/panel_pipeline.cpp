// Pipeline window: every field of core/pipeline_fields.h with its widget, in its section, and the
// A/B table.
#include "panels/panel_pipeline.h"
#include "panels/item_rect.h"

#include "core/pipeline_fields.h"
#include "panels/gui_util.h"
#include "panels/layout.h"

#include <imgui.h>

#include <algorithm>
#include <span>

namespace gbl::ui {

namespace {

// A section the user can fold away; open by default so every row is visible at first.
bool section(char const* label) {
    return ImGui::CollapsingHeader(label, ImGuiTreeNodeFlags_DefaultOpen);
}

void helpTooltip(char const* text) {
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", text);
}
void helpTooltip(std::string_view text) {
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%.*s", int(text.size()), text.data());
}

// A choice as radio buttons, as many to a row as fit. `unavailable` (the mode's row): a reason per
// choice, greyed out where not empty, with the reasons written out below.
void radioRow(PipelineField const& f, PipelineSettings& settings, ModeReasons const* unavailable) {
    ImGui::PushID(f.name.data(), f.name.data() + f.name.size());
    float const right = rowRightEdge();
    int const value = int(f.get(settings));
    for (std::size_t i = 0; i < f.choices.size(); ++i) {
        std::string const name(f.choices[i]);
        std::string const* reason = unavailable && i < unavailable->size() ? &(*unavailable)[i] : nullptr;
        sameLineIfFits(checkItemWidth(name.c_str()), i == 0, right);
        ImGui::BeginDisabled(reason && !reason->empty());
        if (ImGui::RadioButton(name.c_str(), value == int(i))) f.set(settings, double(i));
        ImGui::EndDisabled();
        if (reason && !reason->empty())
            helpTooltip(reason->c_str());
        else
            helpTooltip(i < f.choiceHelp.size() ? f.choiceHelp[i] : f.hoverText());
    }
    ImGui::PopID();
    if (!unavailable) return;
    for (std::string const& reason : *unavailable) {
        if (reason.empty()) continue;
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("%s", reason.c_str());
        ImGui::PopStyleColor();
    }
}

// A choice as a drop-down. The G-buffer layout's and msaa's boxes and entries go to `rects` for
// the frame log (tests click there); the renderer rebuilds its targets on a layout change.
// `reasons`: why each choice cannot be picked, greyed out with it as tooltip where not empty.
void comboRow(PipelineField const& f, PipelineSettings& settings, PipelinePanelRects* rects,
              std::span<std::string const> reasons) {
    std::string const label(f.label);
    bool const layout = f.name == "layout", msaa = f.name == "msaa";
    bool const open = ImGui::BeginCombo(label.c_str(), fieldScriptText(f, settings).c_str());
    if (layout && ImGui::IsItemVisible()) rects->layoutCombo = lastItemRect();
    if (msaa && ImGui::IsItemVisible()) rects->msaaCombo = lastItemRect();
    helpTooltip(f.hoverText());
    if (!open) return;
    int const value = int(f.get(settings));
    for (std::size_t i = 0; i < f.choices.size(); ++i) {
        std::string const* reason = i < reasons.size() && !reasons[i].empty() ? &reasons[i] : nullptr;
        ImGui::BeginDisabled(reason != nullptr);
        if (ImGui::Selectable(std::string(f.choices[i]).c_str(), value == int(i))) f.set(settings, double(i));
        ImGui::EndDisabled();
        if (reason) helpTooltip(reason->c_str());
        ImVec2 const a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
        glm::vec2 const centre((a.x + b.x) * 0.5f, (a.y + b.y) * 0.5f);
        if (layout) rects->layoutItems.push_back(centre);
        if (msaa) rects->msaaItems.push_back(centre);
        if (msaa) rects->msaaGreyed.push_back(reason ? 1 : 0);
    }
    ImGui::EndCombo();
}

// One field, drawn with its widget (core/pipeline_fields.h), greyed out where it does not apply.
void fieldRow(PipelineField const& f, PipelineSettings& settings, ModeReasons const& unavailable,
              PipelinePanelRects* rects, MsaaReasons const* msaaReasons) {
    std::string const label(f.label);
    ImGui::BeginDisabled(!f.appliesTo(settings));
    switch (f.widget) {
        case PipelineWidget::Radio:
            radioRow(f, settings, f.name == "mode" ? &unavailable : nullptr);
            break;
        case PipelineWidget::Combo:
            comboRow(f, settings, rects,
                     f.name == "msaa" && msaaReasons ? std::span<std::string const>(*msaaReasons)
                                                     : std::span<std::string const>());
            break;
        case PipelineWidget::ChoiceCheckbox: {
            bool on = int(f.get(settings)) == f.checkedChoice;
            if (ImGui::Checkbox(label.c_str(), &on)) f.set(settings, on ? double(f.checkedChoice) : 0.0);
            break;
        }
        case PipelineWidget::Checkbox: {
            bool on = f.get(settings) != 0.0;
            if (ImGui::Checkbox(label.c_str(), &on)) f.set(settings, on ? 1.0 : 0.0);
            break;
        }
        case PipelineWidget::Slider:
        case PipelineWidget::LogSlider:
        case PipelineWidget::Drag: {
            float v = float(f.get(settings));
            std::string const format(f.format);
            ImGuiSliderFlags const flags = ImGuiSliderFlags_AlwaysClamp |
                                           (f.widget == PipelineWidget::LogSlider ? ImGuiSliderFlags_Logarithmic : 0);
            bool const changed = f.widget == PipelineWidget::Drag
                                     ? ImGui::DragFloat(label.c_str(), &v, (f.max - f.min) / 1024.0f, f.min, f.max,
                                                        format.c_str(), flags)
                                     : ImGui::SliderFloat(label.c_str(), &v, f.min, f.max, format.c_str(), flags);
            if (changed) f.set(settings, double(v));
            break;
        }
        case PipelineWidget::Colour:
            if (f.rgb) ImGui::ColorEdit3(label.c_str(), &(settings.*f.rgb).x, ImGuiColorEditFlags_Float);
            break;
    }
    ImGui::EndDisabled();
    if (f.widget != PipelineWidget::Radio && f.widget != PipelineWidget::Combo) helpTooltip(f.hoverText());
}

// B's value of one table field, greyed out while B follows A.
void abFieldRow(AbField const& f, std::size_t i, AbState& ab) {
    ImGui::PushID(int(i));
    bool on = ab.overrides[i];
    if (ImGui::Checkbox(f.name.data(), &on)) ab.overrides[i] = on;
    helpTooltip("B changes this setting; unticked, B follows A");
    ImGui::SameLine(ImGui::GetFontSize() * 9.0f);
    ImGui::BeginDisabled(!on);
    ImGui::SetNextItemWidth(-1.0f);
    double const v = f.get(ab.b);
    switch (f.kind) {
        case AbFieldKind::Choice: {
            int index = int(v);
            if (ImGui::BeginCombo("##b", fieldText(f, ab.b).c_str())) {
                for (std::size_t c = 0; c < f.choices.size(); ++c)
                    if (ImGui::Selectable(f.choices[c].data(), index == int(c))) f.set(ab.b, double(c));
                ImGui::EndCombo();
            }
            break;
        }
        case AbFieldKind::Toggle: {
            bool b = v != 0.0;
            if (ImGui::Checkbox("##b", &b)) f.set(ab.b, b ? 1.0 : 0.0);
            break;
        }
        case AbFieldKind::Number: {
            float x = float(v);
            if (ImGui::SliderFloat("##b", &x, f.min, f.max, "%.3g", ImGuiSliderFlags_AlwaysClamp)) f.set(ab.b, x);
            break;
        }
    }
    ImGui::EndDisabled();
    ImGui::PopID();
}

void abSection(AbState& ab, PipelineSettings const& a) {
    if (ImGui::Checkbox("A/B compare in the viewport", &ab.enabled) && ab.enabled) startAb(ab, a);
    helpTooltip("A is the settings above, B the same with the ticked fields changed; the frame renders twice");
    if (!ab.enabled) return;
    int view = int(ab.view);
    ImGui::RadioButton("split", &view, int(AbView::Split));
    ImGui::SameLine();
    ImGui::RadioButton("diff", &view, int(AbView::Diff));
    ab.view = AbView(view);
    if (ab.view == AbView::Diff) {
        // The normal angle compares G-buffer layouts: offered while B changes the layout.
        if (!abComparesLayout(ab)) ab.metric = AbMetric::Lit;
        int metric = int(ab.metric);
        ImGui::RadioButton("lit", &metric, int(AbMetric::Lit));
        helpTooltip("|A - B| of the lit HDR frame");
        ImGui::SameLine();
        ImGui::BeginDisabled(!abComparesLayout(ab));
        ImGui::RadioButton("normal angle", &metric, int(AbMetric::NormalAngle));
        ImGui::EndDisabled();
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip(
                "degrees between A's and B's decoded normals per pixel (tick layout below and set B to\n"
                "classic to see what the current layout's normal encoding loses)");
        ab.metric = AbMetric(metric);
        bool const angle = ab.metric == AbMetric::NormalAngle;
        if (!angle) {
            ImGui::SameLine();
            int mode = int(ab.diffMode);
            ImGui::RadioButton("abs", &mode, int(DiffMode::Absolute));
            ImGui::SameLine();
            ImGui::RadioButton("rel", &mode, int(DiffMode::Relative));
            ab.diffMode = DiffMode(mode);
        }
        float& threshold = angle ? ab.angleThreshold : ab.threshold;
        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.0f);
        ImGui::InputFloat(angle ? "deg" : "threshold", &threshold, 0.0f, 0.0f, "%.2g");
        threshold = std::max(threshold, 0.0f);
        ImGui::SameLine();
        ImGui::Checkbox("heat to threshold", &ab.heatToThreshold);
    }
    std::span<AbField const> const fields = abFields();
    for (std::size_t i = 0; i < fields.size(); ++i) abFieldRow(fields[i], i, ab);
}
}  // namespace

void drawPipelinePanel(PipelineSettings& settings, ModeReasons const& unavailable, AbState* ab,
                       PipelinePanelRects* rects, MsaaReasons const* msaa) {
    PipelinePanelRects unused;
    if (!rects) rects = &unused;
    *rects = {};
    if (ImGui::Begin(windowName(EditorWindow::Pipeline), nullptr)) {
        ImVec2 const pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
        rects->window = {pos.x, pos.y, size.x, size.y};
        // Each section's fields in table order; toggles share a row while they fit, the other
        // widgets take the column, less the width of their label on the right.
        float labelWidth = 0.0f;
        for (PipelineField const& f : pipelineFields())
            if (f.widget != PipelineWidget::Radio && f.widget != PipelineWidget::Checkbox &&
                f.widget != PipelineWidget::ChoiceCheckbox)
                labelWidth = std::max(labelWidth, ImGui::CalcTextSize(std::string(f.label).c_str()).x);
        labelWidth += ImGui::GetStyle().ItemInnerSpacing.x * 2.0f;
        for (std::size_t si = 0; si < kPipelineSectionTitles.size(); ++si) {
            if (!section(kPipelineSectionTitles[si].data())) continue;
            ImGui::PushItemWidth(-labelWidth);
            bool rowStart = true;
            float const right = rowRightEdge();
            for (PipelineField const& f : pipelineFields()) {
                if (f.section != PipelineSection(si)) continue;
                bool const box = f.widget == PipelineWidget::Checkbox || f.widget == PipelineWidget::ChoiceCheckbox;
                if (box) sameLineIfFits(checkItemWidth(std::string(f.label).c_str()), rowStart, right);
                fieldRow(f, settings, unavailable, rects, msaa);
                rowStart = !box;
            }
            ImGui::PopItemWidth();
        }
        if (ab && section("A/B compare")) abSection(*ab, settings);
    }
    ImGui::End();
}

}  // namespace gbl::ui
