// Lights window.
#include "panels/panel_lights.h"
#include "panels/item_rect.h"

#include "core/light_math.h"
#include "model/drag_speed.h"
#include "model/light_list.h"
#include "panels/attenuation_plot.h"
#include "panels/gui_util.h"
#include "panels/layout.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace gbl::ui {

namespace {

char const* radiusKindText(RadiusKind kind) {
    switch (kind) {
        case RadiusKind::Quadratic:
            return "quadratic root";
        case RadiusKind::Linear:
            return "linear (Kq = 0)";
        case RadiusKind::Capped:
            return "never falls off (Kl = Kq = 0): capped";
        case RadiusKind::Zero:
            return "never reaches the threshold: skipped";
    }
    return "";
}

void drawList(LightsPanelState& state, std::vector<PointLight>& lights) {
    float const row = ImGui::GetTextLineHeightWithSpacing();
    float const height = std::min(row * 6.5f, ImGui::GetContentRegionAvail().y * 0.4f);
    beginFramedChild("light-list", ImVec2(0, std::max(height, row * 3.0f)));
    // A selection made elsewhere (a pick in the viewport, undo) is scrolled into the middle of the
    // list; the clipper would not even create its row otherwise.
    if (state.selected != state.listShows) {
        if (state.selected >= 0) {
            float const top = float(state.selected) * row;
            ImGui::SetScrollY(std::max(0.0f, top - (ImGui::GetWindowHeight() - row) * 0.5f));
        }
        state.listShows = state.selected;
    }
    ImGuiListClipper clipper;
    clipper.Begin(int(lights.size()), row);
    while (clipper.Step()) {
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
            PointLight const& l = lights[std::size_t(i)];
            ImGui::PushID(i);
            bool const selected = state.selected == i;
            if (selected) {
                // The picked light stands out, not only by the faint selectable background.
                ImVec2 const p = ImGui::GetCursorScreenPos();
                ImGui::GetWindowDrawList()->AddRectFilled(
                    p, ImVec2(p.x + ImGui::GetContentRegionAvail().x, p.y + ImGui::GetTextLineHeight()),
                    IM_COL32(200, 160, 40, 110));
            }
            ImGui::ColorButton("##c", ImVec4(l.color.r, l.color.g, l.color.b, 1.0f),
                               ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoPicker,
                               ImVec2(ImGui::GetTextLineHeight(), ImGui::GetTextLineHeight()));
            ImGui::SameLine();
            char label[96];
            char const* const name = l.name.empty() ? "light" : l.name.c_str();
            if (l.kind == LightKind::Directional)
                std::snprintf(label, sizeof label, "%3d  %s  directional", i, name);
            else
                std::snprintf(label, sizeof label, "%3d  %s  %sr=%.2f", i, name,
                              l.kind == LightKind::Spot ? "spot " : "", lightRadius(l).radius);
            if (ImGui::Selectable(label, selected)) state.selected = state.listShows = i;
            ImGui::PopID();
        }
    }
    ImGui::EndChild();
}

// The field's help line as the hovered widget's tooltip, with how a log-speed drag moves.
void fieldHelp(LightField const& f) {
    if (!ImGui::IsItemHovered() || f.help.empty()) return;
    std::string tip(f.help);
    if (f.logDrag) tip += "\ndrag: 2% per pixel; Ctrl+click or double-click: type a value";
    ImGui::SetTooltip("%s", tip.c_str());
}

// While an attenuation field is dragged and the plot is not wholly in view (at 1280x720 it lies
// below the Lights window's fold, or its section is closed), the plot follows the pointer in a
// tooltip, ghost included: the curve a drag of Kq changes is on screen during the drag.
void drawPlotPopup(LightsPanelState& state, PointLight const& light, std::optional<float> pixelDistance, bool active) {
    if (!active || state.plotRect.z > 0.0f) return;
    ImGui::BeginTooltip();
    ImGui::TextUnformatted("Attenuation plot (scroll down for the full one)");
    float const w = std::max(280.0f, ImGui::GetFontSize() * 20.0f);
    AttenuationPlotMarks const marks = drawAttenuationPlot(light, state.plotLogScale, ImVec2(w, w * 0.6f),
                                                           state.plotFixedAxis ? state.plotAxisMax : 0.0f,
                                                           pixelDistance, shownPlotGhost(state, light));
    state.plotPopupRect = lastItemRect();
    state.plotPopupRadius = marks.radius;
    ImGui::EndTooltip();
}

// The last item's rectangle (x, y, width, height) in window coordinates; 0 unless it is wholly in
// view (a test's click at a point of it must land on it, not on the next window).
glm::vec4 visibleItemRect() {
    ImVec2 const a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    float const top = ImGui::GetWindowPos().y + ImGui::GetFrameHeight();
    float const bottom = ImGui::GetWindowPos().y + ImGui::GetWindowHeight() - ImGui::GetStyle().WindowPadding.y * 0.5f;
    if (!ImGui::IsItemVisible() || a.y < top || b.y > bottom) return glm::vec4(0.0f);
    return {a.x, a.y, b.x - a.x, b.y - a.y};
}

// The fields the attenuation curve follows (sameAttenuation): a drag of one leaves a ghost.
bool attenuationField(LightField const& f) {
    return f.vector == &PointLight::color || f.name == "kc" || f.name == "kl" || f.name == "kq" ||
           f.name == "intensity" || f.name == "threshold";
}

// What the rows saw this frame: whether an attenuation field is held (or was released this frame,
// whose edit still belongs to the drag) and where the Kq field is (visibleItemRect).
struct RowsSeen {
    bool attenuationHeld = false;
    bool attenuationActive = false;  // held now (the drag goes on), not just released
    glm::vec4 kqRect{0.0f};
};

void noteField(LightField const& f, RowsSeen& seen) {
    if (attenuationField(f) && (ImGui::IsItemActive() || ImGui::IsItemDeactivated())) seen.attenuationHeld = true;
    if (attenuationField(f) && ImGui::IsItemActive()) seen.attenuationActive = true;
    if (f.name == "kq") seen.kqRect = visibleItemRect();
}

// One row of the panel: the kLightFields entries whose row is `row`, with the bounds
// lightFieldBounds() gives (those files and the UI script accept), then the row's name. A vector is
// one widget (the colour a colour editor); scalars share the row. Nothing for a kind that does not
// use the row.
bool drawLightRow(std::string_view row, PointLight& edited, RowsSeen& seen) {
    std::vector<LightField const*> fields;
    for (LightField const& f : kLightFields)
        if (f.row == row) fields.push_back(&f);
    if (fields.empty() || !fields[0]->usedBy(edited.kind)) return false;
    LightField const& first = *fields[0];
    std::string const label(row);
    bool changed = false;
    if (first.vector) {
        glm::vec3& v = edited.*first.vector;
        if (first.range == LightFieldRange::NonNegative) {
            changed = ImGui::ColorEdit3(label.c_str(), &v.x, ImGuiColorEditFlags_Float);
        } else {
            // Moves by 1% of the largest component per pixel, at least the field's step.
            float const reach = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
            LightFieldBounds const b = lightFieldBounds(first, edited);
            changed = ImGui::DragFloat3(label.c_str(), &v.x, proportionalDragSpeed(reach, first.dragStep), b.lo, b.hi,
                                        std::string(first.format).c_str());
        }
        noteField(first, seen);
        fieldHelp(first);
        return changed;
    }
    float const spacing = ImGui::GetStyle().ItemInnerSpacing.x;
    float const n = float(fields.size());
    ImGui::PushItemWidth((ImGui::CalcItemWidth() - (n - 1.0f) * spacing) / n);
    for (std::size_t i = 0; i < fields.size(); ++i) {
        LightField const& f = *fields[i];
        if (i > 0) ImGui::SameLine(0, spacing);
        float& value = f.of(edited);
        // The speed follows the value (model/drag_speed.h); the attenuation terms differ by orders of
        // magnitude, so theirs is a share per pixel: 0.001 to 2 is a few hundred pixels.
        float const speed = f.logDrag ? proportionalDragSpeed(value, f.dragStep, kLogDragShare)
                                      : proportionalDragSpeed(value, f.dragStep);
        LightFieldBounds const b = lightFieldBounds(f, edited);
        changed |= ImGui::DragFloat(("##" + std::string(f.name)).c_str(), &value, speed, b.lo, b.hi,
                                    std::string(f.format).c_str());
        noteField(f, seen);
        fieldHelp(f);
    }
    ImGui::PopItemWidth();
    ImGui::SameLine(0, spacing);
    ImGui::TextUnformatted(label.c_str());
    return changed;
}

// The rows of kLightFields in table order: those only some kinds use first (they appear under the
// Kind combo as the kind changes), then the rest.
std::vector<std::string_view> lightRows() {
    std::vector<std::string_view> kindRows, rows;
    for (LightField const& f : kLightFields) {
        auto& into = f.kinds == kAllLightKinds ? rows : kindRows;
        if (std::find(kindRows.begin(), kindRows.end(), f.row) == kindRows.end() &&
            std::find(rows.begin(), rows.end(), f.row) == rows.end())
            into.push_back(f.row);
    }
    kindRows.insert(kindRows.end(), rows.begin(), rows.end());
    return kindRows;
}

bool drawKindCombo(PointLight& edited) {
    bool changed = false;
    if (ImGui::BeginCombo("Kind", std::string(lightKindName(edited.kind)).c_str())) {
        for (std::size_t i = 0; i < kLightKindNames.size(); ++i) {
            LightKind const k = static_cast<LightKind>(i);
            if (ImGui::Selectable(std::string(kLightKindNames[i]).c_str(), edited.kind == k) && edited.kind != k) {
                edited.kind = k;
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

void drawSelected(LightsPanelState& state, std::vector<PointLight>& lights, std::optional<float> pixelDistance) {
    if (state.selected < 0 || state.selected >= int(lights.size())) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("Select a light in the list or click its cube in the viewport.");
        ImGui::PopStyleColor();
        return;
    }
    // The plot's place, under the list: reserved here and drawn once the fields below have made this
    // frame's edit, so it is in view without scrolling whenever the window is as tall as the list and
    // the plot's least height (the layout gives it that height, panels/layout.h).
    bool const plotShown = lights[std::size_t(state.selected)].kind != LightKind::Directional &&
                           ImGui::CollapsingHeader("Attenuation plot", ImGuiTreeNodeFlags_DefaultOpen);
    ImVec2 plotPos(0.0f, 0.0f), plotSize(0.0f, 0.0f);
    if (plotShown) {
        // Nine lines for the axes and the curve, one more for the legend's row above them.
        float const least = ImGui::GetFontSize() * 9.0f + ImGui::GetTextLineHeightWithSpacing() + 8.0f;
        float const avail = ImGui::GetContentRegionAvail().y - ImGui::GetStyle().ItemSpacing.y;
        plotSize = ImVec2(ImGui::GetContentRegionAvail().x, std::clamp(avail, least, ImGui::GetFontSize() * 12.0f));
        state.plotShortPx = ImGui::GetScrollY() <= 0.0f ? std::max(0.0f, least - avail) : 0.0f;
        plotPos = ImGui::GetCursorScreenPos();
        ImGui::Dummy(plotSize);
    }
    // Short labels on the right, values fill the rest of the narrow side column.
    ImGui::PushItemWidth(-(ImGui::CalcTextSize("Position").x + ImGui::GetStyle().ItemInnerSpacing.x));
    // Widgets edit a copy; the copy replaces the light only when validateLight accepts it.
    PointLight const before = lights[std::size_t(state.selected)];
    PointLight edited = before;
    RowsSeen seen;
    bool changed = false;
    char name[64];
    std::snprintf(name, sizeof name, "%s", edited.name.c_str());
    if (ImGui::InputText("Name", name, sizeof name)) {
        edited.name = name;
        changed = true;
    }
    changed |= drawKindCombo(edited);
    static std::vector<std::string_view> const rows = lightRows();
    for (std::string_view row : rows) changed |= drawLightRow(row, edited, seen);
    state.kqFieldRect = seen.kqRect;

    // Presets are named by the radius they give this light (its brightness and cut-off included).
    int const preset = matchingPreset(edited);
    std::string const presetName =
        preset >= 0 ? presetLabel(edited, kAttenuationPresets[std::size_t(preset)]) : std::string("custom");
    if (ImGui::BeginCombo("Preset", presetName.c_str())) {
        for (std::size_t i = 0; i < kAttenuationPresets.size(); ++i) {
            auto const& p = kAttenuationPresets[i];
            char item[96];
            std::snprintf(item, sizeof item, "%-13s Kl %.4f  Kq %.6f", presetLabel(edited, p).c_str(), p.kl, p.kq);
            if (ImGui::Selectable(item, preset == int(i))) {
                applyPreset(edited, p);
                changed = true;
            }
        }
        ImGui::EndCombo();
    }

    ImGui::PopItemWidth();
    if (changed) {
        auto const error = applyLightEdit(lights, state.selected, edited);
        state.message = error ? *error : std::string();
    }

    PointLight const& light = lights[std::size_t(state.selected)];
    trackPlotGhost(state, seen.attenuationHeld, before, light);
    if (light.kind == LightKind::Directional) {
        ImGui::TextWrapped(
            "Directional: no attenuation and no radius; every mode shades it in its full-screen "
            "pass (Kc, Kl, Kq and the cut-off are kept but unused).");
        return;
    }
    LightRadius const r = lightRadius(light);
    // Drawn after the section below, which tells whether the plot is in view.
    struct PlotPopup {
        LightsPanelState& state;
        PointLight const& light;
        std::optional<float> pixelDistance;
        bool active;
        ~PlotPopup() { drawPlotPopup(state, light, pixelDistance, active); }
    } const popup{state, light, pixelDistance, seen.attenuationActive};
    if (!plotShown) return;
    ImGui::SeparatorText("Attenuation");
    ImGui::Text("Radius %.3f  (%s)", r.radius, radiusKindText(r.kind));
    ImGui::Text("Imax %.3f  Imax/cut %.1f", lightImax(light),
                light.threshold > 0.0f ? lightImax(light) / light.threshold : 0.0f);
    ImGui::Checkbox("log", &state.plotLogScale);
    ImGui::SameLine();
    if (ImGui::Checkbox("fixed axis", &state.plotFixedAxis) && state.plotFixedAxis)
        state.plotAxisMax = r.radius > 0.0f ? r.radius * 1.25f : 1.0f;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("hold the distance axis where it is now, so changing Kq or the cut-off moves the curve");
    if (state.plotFixedAxis) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 5.0f);
        ImGui::DragFloat("##axis", &state.plotAxisMax, 0.05f, 0.1f, 1e4f, "0..%.2f", ImGuiSliderFlags_AlwaysClamp);
    }
    // A spot gets a second, smaller plot: its cone factor against the angle from its axis.
    if (light.kind == LightKind::Spot)
        drawConePlot(light, ImVec2(ImGui::GetContentRegionAvail().x, ImGui::GetFontSize() * 5.0f));
    // The attenuation plot in its place under the list.
    ImVec2 const resume = ImGui::GetCursorScreenPos();
    ImGui::SetCursorScreenPos(plotPos);
    AttenuationPlotMarks const marks =
        drawAttenuationPlot(light, state.plotLogScale, plotSize, state.plotFixedAxis ? state.plotAxisMax : 0.0f,
                            pixelDistance, shownPlotGhost(state, light));
    state.plotRect = visibleItemRect();
    state.plotRadius = marks.radius;
    state.plotGhostRadius = marks.ghostRadius;
    state.plotLight = {light.kc, light.kl, light.kq, lightImax(light), light.threshold};
    ImGui::SetCursorScreenPos(resume);
    ImGui::Dummy(ImVec2(0.0f, 0.0f));
}

}  // namespace

void drawLightsPanel(LightsPanelState& state, std::vector<PointLight>& lights, LightAnimation& animation,
                     Bounds const& sceneBounds, std::optional<float> pixelDistance) {
    state.window = state.plotRect = state.kqFieldRect = state.plotPopupRect = glm::vec4(0.0f);
    state.plotRadius = state.plotGhostRadius = state.plotPopupRadius = -1.0f;
    state.plotShortPx = -1.0f;
    state.plotLight.clear();
    if (ImGui::Begin(windowName(EditorWindow::Lights), nullptr)) {
        if (state.selected >= int(lights.size())) state.selected = int(lights.size()) - 1;
        ImVec2 const pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
        state.window = {pos.x, pos.y, size.x, size.y};
        if (ImGui::Button("Add")) {
            auto const r = addLight(lights, sceneBounds.center() + glm::vec3(0, 1, 0));
            state.message = r.message;
            if (r.index >= 0) state.selected = r.index;
        }
        ImGui::SameLine();
        ImGui::BeginDisabled(state.selected < 0);
        if (ImGui::Button("Duplicate")) {
            auto const r = duplicateLight(lights, state.selected);
            state.message = r.message;
            if (r.index >= 0) state.selected = r.index;
        }
        ImGui::SameLine();
        if (ImGui::Button("Delete")) state.selected = deleteLight(lights, state.selected);
        ImGui::EndDisabled();
        ImGui::SameLine();
        ImGui::Checkbox("Animate", &animation.enabled);

        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.0f);
        ImGui::InputInt("##count", &state.randomCount, 1, 16);
        state.randomCount = std::clamp(state.randomCount, 1, kMaxEditorLights);
        ImGui::SameLine();
        if (ImGui::Button("Add random lights")) {
            auto const r = addRandomLights(lights, state.randomCount, sceneBounds, state.randomSeed);
            state.message = r.message;
        }
        // Wraps in a narrow column instead of cutting the button off.
        sameLineIfFits(ImGui::CalcTextSize("Clear").x + ImGui::GetStyle().FramePadding.x * 2.0f, false, rowRightEdge());
        ImGui::BeginDisabled(lights.empty());
        if (ImGui::Button("Clear")) {
            lights.clear();
            state.selected = -1;
        }
        ImGui::EndDisabled();
        if (animation.enabled) {
            ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
            ImGui::SliderFloat("Speed", &animation.speed, 0.0f, 4.0f, "%.2fx");
        }

        drawList(state, lights);
        if (!state.message.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "%s", state.message.c_str());
        drawSelected(state, lights, pixelDistance);
    }
    ImGui::End();
}

}  // namespace gbl::ui
