// Pipeline window.
#include "panels/panel_pipeline.h"
#include "panels/item_rect.h"

#include "core/pipeline_fields.h"
#include "panels/gui_util.h"
#include "panels/layout.h"

#include <imgui.h>

#include <algorithm>

namespace gbl::ui {

namespace {
// One-line explanations shown on hover: the editor is a teaching tool, the lesson is the point.
constexpr char const* kModeHelp[] = {
    "quad: one full-screen pass evaluates every light at every pixel (cost = pixels x lights)",
    "volumes: one sphere per light, scaled to its radius; only covered pixels are shaded",
    "tiled: a compute pass builds a light list per 16x16 tile, then shades each pixel with its tile's lights",
    "forward: no G-buffer; every object is shaded with every light while it is drawn",
    "clustered: the GPU lists the lights of each 16x16 tile's exponential depth slices; each pixel shades with its "
    "slice's list",
};
constexpr char const* kCullHelp[] = {
    "back: cull back faces; the volume vanishes when the camera is inside it",
    "front: cull front faces and draw the far side; works with the camera inside",
    "none: draw both sides, so each light is applied twice (the classic bug)",
    "flip: back faces normally, front faces for lights whose volume holds the camera",
    "stencil: two passes, mark then shade, so each pixel is shaded once and only if inside",
};
constexpr char const* kBlitHelp[] = {
    "blit: glBlitFramebuffer copies the G-buffer depth so light cubes are hidden by walls",
    "shader: a full-screen pass writes gl_FragDepth from the depth texture (works where blits between formats fail)",
    "off: no depth before the forward pass; light cubes show through walls",
};

// A section the user can fold away; open by default so every row is visible at first.
bool section(char const* label) {
    return ImGui::CollapsingHeader(label, ImGuiTreeNodeFlags_DefaultOpen);
}

void helpTooltip(char const* text) {
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", text);
}

template <class Enum, std::size_t N>
void radioRow(char const* id, Enum& value, std::array<std::string_view, N> const& names, char const* const* help) {
    ImGui::PushID(id);
    float const right = rowRightEdge();
    for (std::size_t i = 0; i < N; ++i) {
        sameLineIfFits(checkItemWidth(names[i].data()), i == 0, right);
        if (ImGui::RadioButton(names[i].data(), value == Enum(i))) value = Enum(i);
        helpTooltip(help[i]);
    }
    ImGui::PopID();
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

// The G-buffer layout (core/gbuffer_layout.h); the renderer rebuilds its targets on change.
// Where the box and its entries are goes to `rects` for the frame log.
void layoutCombo(PipelineSettings& settings, PipelinePanelRects* rects) {
    auto centre = [] {
        ImVec2 const a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
        return glm::vec2((a.x + b.x) * 0.5f, (a.y + b.y) * 0.5f);
    };
    bool const open = ImGui::BeginCombo("G-buffer", enumName(kGBufferLayoutNames, settings.layout).data());
    if (ImGui::IsItemVisible()) {
        rects->layoutCombo = lastItemRect();
    }
    helpTooltip("how the G-buffer stores its quantities; the Pipeline's A/B compare can set side B to classic");
    if (!open) return;
    for (std::size_t i = 0; i < kGBufferLayoutNames.size(); ++i) {
        auto const layout = GBufferLayout(i);
        if (ImGui::Selectable(kGBufferLayoutNames[i].data(), settings.layout == layout)) settings.layout = layout;
        rects->layoutItems.push_back(centre());
    }
    ImGui::EndCombo();
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
                       PipelinePanelRects* rects) {
    PipelinePanelRects unused;
    if (!rects) rects = &unused;
    *rects = {};
    if (ImGui::Begin(windowName(EditorWindow::Pipeline), nullptr)) {
        ImVec2 const pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
        rects->window = {pos.x, pos.y, size.x, size.y};
        float const right = rowRightEdge();
        if (section("Lighting mode")) {
            for (std::size_t i = 0; i < kLightingModeNames.size(); ++i) {
                auto const mode = LightingMode(i);
                std::string const& reason = unavailable[i];
                sameLineIfFits(checkItemWidth(kLightingModeNames[i].data()), i == 0, right);
                ImGui::BeginDisabled(!reason.empty());
                if (ImGui::RadioButton(kLightingModeNames[i].data(), settings.mode == mode)) settings.mode = mode;
                ImGui::EndDisabled();
                helpTooltip(reason.empty() ? kModeHelp[i] : reason.c_str());
            }
            for (std::string const& reason : unavailable) {
                if (reason.empty()) continue;
                ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
                ImGui::TextWrapped("%s", reason.c_str());
                ImGui::PopStyleColor();
            }
        }

        if (section("Volume cull mode (volumes only)")) {
            // Greyed out, never hidden, in the other modes: rows below keep their place whatever the
            // mode, so a click aimed at a checkbox does not land on another one.
            bool const volumes = settings.mode == LightingMode::Volumes;
            ImGui::BeginDisabled(!volumes);
            radioRow("cull", settings.cull, kCullModeNames, kCullHelp);
            PipelineField const& scale = *findPipelineField("volume_scale");
            ImGui::SetNextItemWidth(ImGui::GetFontSize() * 10.0f);
            ImGui::SliderFloat("Volume scale", &settings.volumeScale, scale.min, scale.max, "%.2f",
                               ImGuiSliderFlags_AlwaysClamp);
            helpTooltip(
                "1: each volume just encloses its light's radius; below 1 its faces cut the light off "
                "(dark rims), above 1 it shades pixels the light cannot reach");
            ImGui::EndDisabled();
        }

        if (section("Depth before the forward pass")) {
            radioRow("blit", settings.depthCopy, kDepthCopyNames, kBlitHelp);
        }

        if (section("Overlays and views")) {
            ImGui::Checkbox("Light cubes", &settings.lightCubes);
            sameLineIfFits(checkItemWidth("Volume wireframes"), false, right);
            ImGui::Checkbox("Volume wireframes", &settings.volumeWireframes);
            ImGui::BeginDisabled(!settings.volumeWireframes);
            ImGui::Checkbox("Selected light's volume only", &settings.wireframesSelectedOnly);
            ImGui::EndDisabled();
            helpTooltip("32 volumes at once are a tangle: outline only the light selected in the Lights window");
            bool heatmap = settings.view == DebugView::Heatmap;
            if (ImGui::Checkbox("Coverage heatmap", &heatmap))
                settings.view = heatmap ? DebugView::Heatmap : DebugView::Final;
            helpTooltip(
                "per pixel: how many lights the mode evaluated (volumes, tile or cluster list) and how many\n"
                "lit it; colours in bins 0, 1, 2, 4, 8, 16, 32, 64+, dim where the lights evaluated did not light it");
            sameLineIfFits(checkItemWidth("Normal maps"), false, right);
            ImGui::Checkbox("Normal maps", &settings.normalMaps);
        }

        if (section("Shading")) {
            // Labels on the right take their own width; the fields get the rest of the column.
            ImGui::PushItemWidth(-ImGui::CalcTextSize("Shininess").x - ImGui::GetStyle().ItemInnerSpacing.x * 2.0f);
            ImGui::ColorEdit3("Ambient", &settings.ambient.x, ImGuiColorEditFlags_Float);
            PipelineField const& shininess = *findPipelineField("shininess");  // ranges: core/pipeline_fields.h
            PipelineField const& exposure = *findPipelineField("exposure");
            ImGui::DragFloat("Shininess", &settings.shininess, 0.5f, shininess.min, shininess.max, "%.1f",
                             ImGuiSliderFlags_AlwaysClamp);
            int tonemap = int(settings.tonemap);
            char const* tonemapItems[] = {kTonemapNames[0].data(), kTonemapNames[1].data(), kTonemapNames[2].data()};
            if (ImGui::Combo("Tonemap", &tonemap, tonemapItems, 3)) settings.tonemap = Tonemap(tonemap);
            ImGui::SliderFloat("Exposure", &settings.exposure, exposure.min, exposure.max, "%.2f",
                               ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
            layoutCombo(settings, rects);
            // One lit target, or diffuse and specular light in two plus a combine pass (docs/lighting.md).
            int accumulation = int(settings.accumulation);
            char const* accumulationItems[] = {kLightAccumulationNames[0].data(), kLightAccumulationNames[1].data()};
            if (ImGui::Combo("Targets", &accumulation, accumulationItems, 2))
                settings.accumulation = LightAccumulation(accumulation);
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip(
                    "single: one lit target\nsplit: diffuse and specular light targets, then a combine "
                    "pass (forward mode keeps one target)");
            // The lighting equation: ours, or LearnOpenGL's deferred shader's (docs/lighting.md).
            int shading = int(settings.shading);
            char const* shadingItems[] = {kShadingModelNames[0].data(), kShadingModelNames[1].data()};
            if (ImGui::Combo("Equation", &shading, shadingItems, 2)) settings.shading = ShadingModel(shading);
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip(
                    "gbuffer-lab: windowed attenuation, zero from each light's radius on (docs/lighting.md)\n"
                    "learnopengl: LearnOpenGL's deferred lighting shader: 1/(Kc + Kl d + Kq d^2) with no window,\n"
                    "specular not gated by N.L; quad and forward light every pixel with every light, volumes,\n"
                    "tiled and clustered stop at the radius. A manifest with \"shading\": \"learnopengl\" also\n"
                    "sets ambient 0.1 and shininess 16, as that shader does.");
            ImGui::PopItemWidth();
        }
        if (ab && section("A/B compare")) abSection(*ab, settings);
    }
    ImGui::End();
}

}  // namespace gbl::ui
