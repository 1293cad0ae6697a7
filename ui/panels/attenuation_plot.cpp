// The attenuation and cone plots, drawn with ImPlot.
#include "panels/attenuation_plot.h"

#include "core/light_math.h"

#include <implot.h>
#include <implot_internal.h>  // the plot's items and legend, for the marks

#include <algorithm>
#include <cmath>

namespace gbl::ui {

AttenuationCurve sampleAttenuationCurve(PointLight const& light, int samples, float maxDistance) {
    AttenuationCurve c;
    LightRadius const r = lightRadius(light);
    c.radius = r.radius;
    // Show a quarter past the radius so the curve visibly reaches zero; a light without a
    // radius still gets a short axis so the plot is not empty.
    c.maxDistance = maxDistance > 0.0f ? maxDistance : r.radius > 0.0f ? r.radius * 1.25f : 1.0f;
    float const imax = lightImax(light);
    samples = std::max(samples, 2);
    for (int i = 0; i < samples; ++i) {
        float const d = c.maxDistance * float(i) / float(samples - 1);
        c.distance.push_back(d);
        c.classic.push_back(imax * attenuation(light.kc, light.kl, light.kq, d));
        c.applied.push_back(imax * windowedAttenuation(light, r.radius, d));
    }
    return c;
}

namespace {
ImVec4 colour(int r, int g, int b, int a) {
    return ImVec4(float(r) / 255.0f, float(g) / 255.0f, float(b) / 255.0f, float(a) / 255.0f);
}

ImPlotSpec lineSpec(ImVec4 c, float weight, ImPlotItemFlags flags = 0) {
    ImPlotSpec spec;
    spec.LineColor = c;
    spec.LineWeight = weight;
    spec.Flags = flags;
    return spec;
}

// Values drawn on a log axis: zero (past the radius) held at the axis' bottom, so the curve ends
// on the axis instead of leaving the plot.
std::vector<float> shown(std::vector<float> const& values, float bottom) {
    std::vector<float> out(values);
    if (bottom > 0.0f)
        for (float& v : out) v = std::max(v, bottom);
    return out;
}

// The plot's frame and axes: both axes held where the model puts them (auto-ranged from the light,
// or the fixed axis), not panned or zoomed by the mouse.
constexpr ImPlotFlags kPlotFlags = ImPlotFlags_NoMenus | ImPlotFlags_NoBoxSelect | ImPlotFlags_NoMouseText;
// A horizontal marked line with no legend entry (the flags are two enums).
constexpr ImPlotItemFlags kHorizontalUnlisted = int(ImPlotItemFlags_NoLegend) | int(ImPlotInfLinesFlags_Horizontal);
constexpr ImPlotAxisFlags kAxisFlags = ImPlotAxisFlags_Lock | ImPlotAxisFlags_NoMenus | ImPlotAxisFlags_NoHighlight;
// The legend's labels (the ghost's first while one is shown), as the plot draws them below.
constexpr char const* kGhostLabel = "before the drag";
constexpr char const* kClassicLabel = "1/(Kc+Kl d+Kq d²)";
constexpr char const* kAppliedLabel = "applied";

// Whether the legend's entries fit in one row across a plot `width` wide (ImPlot's horizontal
// legend: each entry an icon a line high and its label, between the legend's paddings).
bool legendFitsAbove(bool withGhost, float width) {
    ImPlotStyle const& style = ImPlot::GetStyle();
    float const line = ImGui::GetTextLineHeight();
    float w = 2.0f * (style.LegendInnerPadding.x + style.LegendPadding.x);
    for (char const* label : {kGhostLabel, kClassicLabel, kAppliedLabel}) {
        if (label == kGhostLabel && !withGhost) continue;
        w += line + ImGui::CalcTextSize(label, nullptr, true).x + style.LegendSpacing.x;
    }
    return w <= width;
}
}  // namespace

float attenuationPlotAxis(PointLight const& light, float fixedMaxDistance, PointLight const* ghost) {
    if (fixedMaxDistance > 0.0f) return fixedMaxDistance;
    if (!ghost) return 0.0f;
    float const r = std::max(lightRadius(light).radius, lightRadius(*ghost).radius);
    return r > 0.0f ? r * 1.25f : 0.0f;
}

AttenuationPlotMarks drawAttenuationPlot(PointLight const& light, bool logScale, ImVec2 size, float fixedMaxDistance,
                                         std::optional<float> pixelDistance, PointLight const* ghost) {
    float const axisMax = attenuationPlotAxis(light, fixedMaxDistance, ghost);
    AttenuationCurve const c = sampleAttenuationCurve(light, 128, axisMax);
    std::optional<AttenuationCurve> g;
    if (ghost) g = sampleAttenuationCurve(*ghost, 128, c.maxDistance);
    AttenuationPlotMarks marks;
    marks.radius = c.radius;
    marks.ghostRadius = g ? g->radius : -1.0f;

    float peak = std::max(c.classic.empty() ? 1.0f : c.classic.front(), light.threshold * 2.0f);
    if (g && !g->classic.empty()) peak = std::max(peak, g->classic.front());
    float const yTop = peak * 1.05f;
    float const yBottom = logScale ? light.threshold * 0.1f : 0.0f;
    // A height at fraction f of the value axis (of its logarithm on a log axis): the marks' labels sit
    // low in the plot, clear of the curves' fall at the left.
    auto level = [&](double f) {
        return logScale ? double(yBottom) * std::pow(double(yTop) / double(yBottom), f)
                        : double(yBottom) + f * double(yTop - yBottom);
    };
    ImVec4 const radiusColour = colour(90, 200, 255, 220), pixelColour = colour(255, 160, 0, 220);
    ImVec4 const thresholdColour = colour(230, 180, 60, 200);

    // One group: the caller's last item is the whole plot (its rectangle goes to the frame log).
    ImGui::BeginGroup();
    if (ImPlot::BeginPlot("##attenuation", size, kPlotFlags)) {
        ImPlot::SetupAxes(fixedMaxDistance > 0.0f ? "distance (axis fixed)" : "distance", "intensity", kAxisFlags,
                          kAxisFlags);
        if (logScale) ImPlot::SetupAxisScale(ImAxis_Y1, ImPlotScale_Log10);
        ImPlot::SetupAxisLimits(ImAxis_X1, 0.0, double(c.maxDistance), ImPlotCond_Always);
        ImPlot::SetupAxisLimits(ImAxis_Y1, double(yBottom), double(yTop), ImPlotCond_Always);
        // The legend in one row above the plotting area where that row fits the plot's width: inside
        // its corner it covered the radius's label on a short plot ("r = 4.95" at 1280x720, issue 46).
        ImPlotLegendFlags const legend = ImPlotLegendFlags_NoButtons | ImPlotLegendFlags_NoMenus;
        bool const legendAbove =
            legendFitsAbove(ghost != nullptr, size.x > 0.0f ? size.x : ImGui::GetContentRegionAvail().x);
        // The radius's label high in the plot, clear of the pixel's label at its foot, where the
        // legend leaves that corner free.
        double const radiusLevel = level(legendAbove ? 0.6 : 0.3);
        if (legendAbove)
            ImPlot::SetupLegend(ImPlotLocation_North,
                                legend | ImPlotLegendFlags_Outside | ImPlotLegendFlags_Horizontal);
        else
            ImPlot::SetupLegend(ImPlotLocation_NorthEast, legend);
        int const n = int(c.distance.size());

        // The threshold: where the classic curve crosses it is, by definition, the radius.
        ImPlot::PlotInfLines("##threshold", &light.threshold, 1, lineSpec(thresholdColour, 1.0f, kHorizontalUnlisted));
        ImPlot::Annotation(0.0, double(light.threshold), ImVec4(0, 0, 0, 0), ImVec2(4, -2), true, "threshold");
        if (ghost && ghost->threshold != light.threshold)
            ImPlot::PlotInfLines("##ghost threshold", &ghost->threshold, 1,
                                 lineSpec(colour(230, 180, 60, 80), 1.0f, kHorizontalUnlisted));
        // The ghost's radius, faint, where the radius was when the drag began; then the radius.
        if (g && g->radius > 0.0f && g->radius <= c.maxDistance)
            ImPlot::PlotInfLines("##ghost radius", &g->radius, 1,
                                 lineSpec(colour(90, 200, 255, 90), 1.5f, ImPlotItemFlags_NoLegend));
        if (c.radius > 0.0f && c.radius <= c.maxDistance)
            ImPlot::PlotInfLines("##radius", &c.radius, 1, lineSpec(radiusColour, 1.5f, ImPlotItemFlags_NoLegend));
        if (c.radius > 0.0f && (c.radius <= c.maxDistance || g)) {
            // "r = OLD -> NEW" while a ghost is shown; held inside the plot when past the axis.
            if (g)
                ImPlot::Annotation(double(std::min(c.radius, c.maxDistance)), radiusLevel, radiusColour, ImVec2(4, 0),
                                   true, "r = %.2f → %.2f", g->radius, c.radius);
            else
                ImPlot::Annotation(double(std::min(c.radius, c.maxDistance)), radiusLevel, radiusColour, ImVec2(4, 0),
                                   true, "r = %.2f", c.radius);
        }
        if (pixelDistance && *pixelDistance > c.maxDistance) {
            ImPlot::Annotation(double(c.maxDistance), level(0.12), pixelColour, ImVec2(-4, 0), true, "pixel %.2f →",
                               *pixelDistance);
        } else if (pixelDistance && *pixelDistance >= 0.0f) {
            // The inspected pixel: where it sits on the curve is what the light adds there.
            float const d = *pixelDistance;
            ImPlot::PlotInfLines("##pixel", &d, 1, lineSpec(pixelColour, 1.0f, ImPlotItemFlags_NoLegend));
            ImPlot::Annotation(double(d), level(0.12), pixelColour, ImVec2(4, 0), true, "pixel %.2f", d);
        }
        // The ghost under the curve (the applied curve as it was when the drag began), the textbook
        // form faint, and bright what the renderer adds.
        if (g) {
            std::vector<float> const ghostValues = shown(g->applied, yBottom);
            ImPlot::PlotLine(kGhostLabel, g->distance.data(), ghostValues.data(), n,
                             lineSpec(colour(255, 255, 255, 80), 2.0f));
        }
        std::vector<float> const classic = shown(c.classic, yBottom), applied = shown(c.applied, yBottom);
        ImPlot::PlotLine(kClassicLabel, c.distance.data(), classic.data(), n,
                         lineSpec(colour(150, 150, 150, 160), 1.0f));
        ImPlot::PlotLine(kAppliedLabel, c.distance.data(), applied.data(), n,
                         lineSpec(colour(255, 255, 255, 255), 2.0f));

        ImPlotRect const limits = ImPlot::GetPlotLimits();
        marks.axisMax = float(limits.X.Max);
        marks.valueMax = float(limits.Y.Max);
        ImPlotItemGroup& items = ImPlot::GetCurrentPlot()->Items;
        for (int i = 0; i < items.GetLegendCount(); ++i) marks.legend.emplace_back(items.GetLegendLabel(i));
        for (int i = 0; i < items.GetItemCount(); ++i) marks.items += items.GetItemByIndex(i)->SeenThisFrame ? 1 : 0;
        if (ImPlot::IsPlotHovered() && c.maxDistance > 0.0f) {
            float const d = std::clamp(float(ImPlot::GetPlotMousePos().x), 0.0f, c.maxDistance);
            float const imax = lightImax(light);
            ImGui::SetTooltip(
                "d = %.3f\nclassic Imax/(Kc+Kl d+Kq d^2) = %.4f\napplied (windowed) = %.4f\nthreshold = %.4f", d,
                imax * attenuation(light.kc, light.kl, light.kq, d), imax * windowedAttenuation(light, c.radius, d),
                light.threshold);
        }
        ImPlot::EndPlot();
    }
    ImGui::EndGroup();
    return marks;
}

ConeCurve sampleConeCurve(PointLight const& light, int samples) {
    ConeCurve c;
    c.maxDegrees = std::min(std::max(light.outerConeDeg * 1.25f, 1.0f), 180.0f);
    SpotCone const cone = spotCone(light);
    samples = std::max(samples, 2);
    for (int i = 0; i < samples; ++i) {
        float const a = c.maxDegrees * float(i) / float(samples - 1);
        c.degrees.push_back(a);
        c.factor.push_back(spotConeFactor(cone, std::cos(glm::radians(a))));
    }
    return c;
}

void drawConePlot(PointLight const& light, ImVec2 size) {
    ConeCurve const c = sampleConeCurve(light, 96);
    if (!ImPlot::BeginPlot("##cone", size, kPlotFlags | ImPlotFlags_NoLegend)) return;
    ImPlot::SetupAxes("degrees from the axis", "cone factor", kAxisFlags, kAxisFlags);
    ImPlot::SetupAxisLimits(ImAxis_X1, 0.0, double(c.maxDegrees), ImPlotCond_Always);
    ImPlot::SetupAxisLimits(ImAxis_Y1, 0.0, 1.05, ImPlotCond_Always);
    float const angles[] = {light.innerConeDeg, light.outerConeDeg};
    ImPlot::PlotInfLines("##cone angles", angles, 2, lineSpec(colour(90, 200, 255, 200), 1.0f));
    ImPlot::PlotLine("cone factor", c.degrees.data(), c.factor.data(), int(c.degrees.size()),
                     lineSpec(colour(255, 255, 255, 255), 2.0f));
    if (ImPlot::IsPlotHovered()) {
        float const deg = std::clamp(float(ImPlot::GetPlotMousePos().x), 0.0f, c.maxDegrees);
        ImGui::SetTooltip("angle = %.2f deg\nsaturate((cos a - cos outer) / (cos inner - cos outer))^2 = %.4f", deg,
                          spotConeFactor(spotCone(light), std::cos(glm::radians(deg))));
    }
    ImPlot::EndPlot();
}

}  // namespace gbl::ui
