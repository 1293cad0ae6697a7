// Attenuation plot drawn with ImDrawList.
#include "panels/attenuation_plot.h"

#include "core/light_math.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

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
struct Axes {
    ImVec2 min, max;
    float maxDistance;
    float yTop, yBottom;  // value range, bottom > 0 on a log axis
    bool log;

    ImVec2 at(float d, float v) const {
        float t;
        if (log) {
            float const lv = std::log10(std::max(v, yBottom));
            t = (lv - std::log10(yBottom)) / (std::log10(yTop) - std::log10(yBottom));
        } else {
            t = (v - yBottom) / (yTop - yBottom);
        }
        t = std::clamp(t, 0.0f, 1.0f);
        return ImVec2(min.x + (max.x - min.x) * d / maxDistance, max.y - (max.y - min.y) * t);
    }
};

void polyline(ImDrawList* dl, Axes const& axes, AttenuationCurve const& c, std::vector<float> const& values,
              ImU32 colour, float thickness) {
    for (std::size_t i = 1; i < values.size(); ++i)
        dl->AddLine(axes.at(c.distance[i - 1], values[i - 1]), axes.at(c.distance[i], values[i]), colour, thickness);
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
    AttenuationPlotMarks marks{c.radius, g ? g->radius : -1.0f};
    ImDrawList* dl = ImGui::GetWindowDrawList();
    ImVec2 const p0 = ImGui::GetCursorScreenPos();
    ImVec2 const p1(p0.x + size.x, p0.y + size.y);
    ImGui::InvisibleButton("attenuation-plot", size);
    bool const hovered = ImGui::IsItemHovered();

    float peak = std::max(c.classic.empty() ? 1.0f : c.classic.front(), light.threshold * 2.0f);
    if (g && !g->classic.empty()) peak = std::max(peak, g->classic.front());
    Axes const axes{ImVec2(p0.x + 4, p0.y + 14),
                    ImVec2(p1.x - 4, p1.y - 14),
                    c.maxDistance,
                    peak * 1.05f,
                    logScale ? light.threshold * 0.1f : 0.0f,
                    logScale};

    dl->AddRectFilled(p0, p1, IM_COL32(20, 22, 26, 255));
    dl->AddRect(p0, p1, IM_COL32(90, 90, 100, 255));
    // Threshold: where the classic curve crosses it is, by definition, the radius.
    ImVec2 const t0 = axes.at(0.0f, light.threshold), t1 = axes.at(c.maxDistance, light.threshold);
    dl->AddLine(t0, t1, IM_COL32(230, 180, 60, 200), 1.0f);
    dl->AddText(ImVec2(t1.x - 70, t1.y - 14), IM_COL32(230, 180, 60, 255), "threshold");
    if (ghost && ghost->threshold != light.threshold) {
        ImVec2 const g0 = axes.at(0.0f, ghost->threshold), g1 = axes.at(c.maxDistance, ghost->threshold);
        dl->AddLine(g0, g1, IM_COL32(230, 180, 60, 80), 1.0f);
    }
    if (g && g->radius > 0.0f && g->radius <= c.maxDistance) {
        // The ghost's radius: a dashed, faint line where the radius was when the drag began.
        ImVec2 const r0 = axes.at(g->radius, axes.yTop), r1 = axes.at(g->radius, axes.yBottom);
        for (float y = r0.y; y < r1.y; y += 8.0f)
            dl->AddLine(ImVec2(r0.x, y), ImVec2(r0.x, std::min(y + 4.0f, r1.y)), IM_COL32(90, 200, 255, 110), 1.5f);
    }
    if (c.radius > 0.0f && c.radius <= c.maxDistance) {
        ImVec2 const r0 = axes.at(c.radius, axes.yTop), r1 = axes.at(c.radius, axes.yBottom);
        dl->AddLine(r0, r1, IM_COL32(90, 200, 255, 220), 1.5f);
    }
    if (c.radius > 0.0f && (c.radius <= c.maxDistance || g)) {
        // Beside the radius mark, or while a ghost is shown "r = OLD → NEW" at the right end of the
        // row when it does not fit beside it.
        char label[64];
        if (g)
            std::snprintf(label, sizeof label, "r = %.2f → %.2f", g->radius, c.radius);
        else
            std::snprintf(label, sizeof label, "r = %.2f", c.radius);
        float const w = ImGui::CalcTextSize(label).x;
        float const x = axes.at(std::min(c.radius, c.maxDistance), axes.yTop).x;
        dl->AddText(ImVec2(std::clamp(x + 3, p0.x + 2, std::max(p0.x + 2, p1.x - w - 4)), p0.y + 1),
                    IM_COL32(90, 200, 255, 255), label);
    }
    if (pixelDistance && *pixelDistance > c.maxDistance) {
        // Past the axis: said at its end, below the legend (the threshold's label holds the bottom).
        char label[48];
        std::snprintf(label, sizeof label, "pixel at %.2f: past the axis", *pixelDistance);
        float const w = ImGui::CalcTextSize(label).x;
        dl->AddText(ImVec2(std::max(p1.x - w - 6, p0.x + 2), p0.y + 58), IM_COL32(255, 160, 0, 255), label);
    } else if (pixelDistance && *pixelDistance >= 0.0f) {
        // The inspected pixel: where it sits on the curve is what the light adds there.
        ImVec2 const q0 = axes.at(*pixelDistance, axes.yTop), q1 = axes.at(*pixelDistance, axes.yBottom);
        dl->AddLine(q0, q1, IM_COL32(255, 160, 0, 220), 1.0f);
        char label[48];
        std::snprintf(label, sizeof label, "pixel %.2f", *pixelDistance);
        float const w = ImGui::CalcTextSize(label).x;
        dl->AddText(ImVec2(std::clamp(q0.x + 3, p0.x + 2, p1.x - w - 2), p0.y + 58), IM_COL32(255, 160, 0, 255), label);
    }
    // The ghost under the curve: the applied curve as it was when the drag began.
    if (g) polyline(dl, axes, *g, g->applied, IM_COL32(255, 255, 255, 80), 2.0f);
    polyline(dl, axes, c, c.classic, IM_COL32(150, 150, 150, 160), 1.0f);
    polyline(dl, axes, c, c.applied, IM_COL32(255, 255, 255, 255), 2.0f);
    // Legend, top right, where a falling curve leaves room: the bright curve is what the renderer
    // adds, the faint one the textbook form. On a box of the plot's background, so that in a narrow
    // plot the radius line (at 80 % of the axis) passes behind the text instead of through it.
    struct LegendEntry {
        ImU32 colour;
        char const* text;
    };
    LegendEntry const entries[] = {{IM_COL32(255, 255, 255, 255), "applied"},
                                   {IM_COL32(150, 150, 150, 255), "1/(Kc+Kl d+Kq d²)"},
                                   {IM_COL32(255, 255, 255, 110), "before the drag"}};
    int const shown = g ? 3 : 2;
    float legendWidth = 0.0f;
    for (int i = 0; i < shown; ++i) legendWidth = std::max(legendWidth, ImGui::CalcTextSize(entries[i].text).x);
    float const legendX = std::max(p0.x + 2, p1.x - legendWidth - 6);
    dl->AddRectFilled(ImVec2(legendX - 3, p0.y + 15), ImVec2(p1.x - 2, p0.y + 17 + 14.0f * float(shown)),
                      IM_COL32(20, 22, 26, 225));
    for (int i = 0; i < shown; ++i) {
        float const x = std::max(p0.x + 2, p1.x - ImGui::CalcTextSize(entries[i].text).x - 6);
        dl->AddText(ImVec2(x, p0.y + 16 + 14.0f * float(i)), entries[i].colour, entries[i].text);
    }
    char axisLabel[64];
    std::snprintf(axisLabel, sizeof axisLabel, "0 .. %.2f units%s%s", c.maxDistance, logScale ? "  (log)" : "",
                  fixedMaxDistance > 0.0f ? "  (fixed)" : "");
    dl->AddText(ImVec2(p0.x + 4, p1.y - 14), IM_COL32(160, 160, 160, 255), axisLabel);

    if (hovered && c.maxDistance > 0.0f) {
        float const mx = ImGui::GetIO().MousePos.x;
        float const d = std::clamp((mx - axes.min.x) / (axes.max.x - axes.min.x), 0.0f, 1.0f) * c.maxDistance;
        dl->AddLine(ImVec2(mx, p0.y), ImVec2(mx, p1.y), IM_COL32(255, 255, 255, 60));
        float const imax = lightImax(light);
        ImGui::SetTooltip("d = %.3f\nclassic Imax/(Kc+Kl d+Kq d^2) = %.4f\napplied (windowed) = %.4f\nthreshold = %.4f",
                          d, imax * attenuation(light.kc, light.kl, light.kq, d),
                          imax * windowedAttenuation(light, c.radius, d), light.threshold);
    }
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
    ImDrawList* dl = ImGui::GetWindowDrawList();
    ImVec2 const p0 = ImGui::GetCursorScreenPos();
    ImVec2 const p1(p0.x + size.x, p0.y + size.y);
    ImGui::InvisibleButton("cone-plot", size);
    bool const hovered = ImGui::IsItemHovered();
    ImVec2 const lo(p0.x + 4, p0.y + 14), hi(p1.x - 4, p1.y - 14);
    auto at = [&](float deg, float v) {
        return ImVec2(lo.x + (hi.x - lo.x) * deg / c.maxDegrees, hi.y - (hi.y - lo.y) * std::clamp(v, 0.0f, 1.0f));
    };
    dl->AddRectFilled(p0, p1, IM_COL32(20, 22, 26, 255));
    dl->AddRect(p0, p1, IM_COL32(90, 90, 100, 255));
    for (float deg : {light.innerConeDeg, light.outerConeDeg})
        dl->AddLine(at(deg, 1.0f), at(deg, 0.0f), IM_COL32(90, 200, 255, 200), 1.0f);
    for (std::size_t i = 1; i < c.factor.size(); ++i)
        dl->AddLine(at(c.degrees[i - 1], c.factor[i - 1]), at(c.degrees[i], c.factor[i]), IM_COL32(255, 255, 255, 255),
                    2.0f);
    dl->AddText(ImVec2(p0.x + 6, p0.y + 1), IM_COL32(255, 255, 255, 255), "cone factor");
    char axisLabel[64];
    std::snprintf(axisLabel, sizeof axisLabel, "0 .. %.1f deg from the axis", c.maxDegrees);
    dl->AddText(ImVec2(p0.x + 4, p1.y - 14), IM_COL32(160, 160, 160, 255), axisLabel);
    if (hovered) {
        float const mx = ImGui::GetIO().MousePos.x;
        float const deg = std::clamp((mx - lo.x) / (hi.x - lo.x), 0.0f, 1.0f) * c.maxDegrees;
        dl->AddLine(ImVec2(mx, p0.y), ImVec2(mx, p1.y), IM_COL32(255, 255, 255, 60));
        ImGui::SetTooltip("angle = %.2f deg\nsaturate((cos a - cos outer) / (cos inner - cos outer))^2 = %.4f", deg,
                          spotConeFactor(spotCone(light), std::cos(glm::radians(deg))));
    }
}

}  // namespace gbl::ui
