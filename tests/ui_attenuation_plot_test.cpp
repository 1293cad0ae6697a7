// The attenuation plot shows the renderer's numbers: the applied curve ends at the radius, the
// classic curve meets the threshold there; ImPlot is given the curves, the marks and the axes.
#include "core/light_math.h"
#include "panels/attenuation_plot.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <implot.h>
#include <implot_internal.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

using namespace gbl;
using namespace gbl::ui;

TEST(UiAttenuationPlot, CurvesMeetThresholdAndZeroAtTheRadius) {
    PointLight light;
    light.color = {1.0f, 0.5f, 0.25f};
    light.intensity = 2.0f;
    AttenuationCurve const c = sampleAttenuationCurve(light, 257);
    float const r = lightRadius(light).radius;
    EXPECT_FLOAT_EQ(c.radius, r);
    EXPECT_FLOAT_EQ(c.maxDistance, r * 1.25f);
    ASSERT_EQ(c.distance.size(), 257u);
    float const imax = lightImax(light);
    EXPECT_FLOAT_EQ(c.classic.front(), imax / light.kc);
    // The classic curve at the radius is the threshold: the definition of the radius.
    EXPECT_NEAR(imax * attenuation(light.kc, light.kl, light.kq, r), light.threshold, 1e-5f);
    for (std::size_t i = 0; i < c.distance.size(); ++i) {
        EXPECT_LE(c.applied[i], c.classic[i]);
        if (c.distance[i] >= r) {
            EXPECT_EQ(c.applied[i], 0.0f) << "d = " << c.distance[i];
        }
        if (i > 0) {
            EXPECT_LE(c.applied[i], c.applied[i - 1]);  // never brighter further away
        }
    }
    EXPECT_GT(c.applied[std::size_t(100)], 0.0f);  // 100/256 of 1.25 r is inside the radius
}

TEST(UiAttenuationPlot, LightBelowThresholdHasAnAxisButNoRadius) {
    PointLight light;
    light.intensity = 0.01f;  // Imax below threshold * Kc: never lights anything
    AttenuationCurve const c = sampleAttenuationCurve(light, 16);
    EXPECT_EQ(c.radius, 0.0f);
    EXPECT_GT(c.maxDistance, 0.0f);
    for (float v : c.applied) EXPECT_EQ(v, 0.0f);
}

// Issue 26: with the axis held, a smaller Kq (a larger radius) moves the curve instead of
// rescaling the axis under it: the value at a fixed distance grows.
TEST(UiAttenuationPlot, AFixedAxisShowsAChangeOfKq) {
    PointLight light;
    light.kq = 2.4f;
    float const axis = 2.0f * lightRadius(light).radius;
    AttenuationCurve const before = sampleAttenuationCurve(light, 33, axis);
    light.kq = 0.84f;
    AttenuationCurve const after = sampleAttenuationCurve(light, 33, axis);
    EXPECT_FLOAT_EQ(before.maxDistance, axis);
    EXPECT_FLOAT_EQ(after.maxDistance, axis);
    EXPECT_FLOAT_EQ(before.distance.back(), after.distance.back());
    EXPECT_GT(after.radius, before.radius);
    std::size_t const middle = 8;  // a quarter of the axis: inside both radii
    ASSERT_LT(before.distance[middle], before.radius);
    EXPECT_GT(after.applied[middle], before.applied[middle]);
}

TEST(UiAttenuationPlot, TheConePlotIsTheSpotsFactorFromOneToZero) {
    PointLight light;
    light.kind = LightKind::Spot;
    light.innerConeDeg = 20.0f;
    light.outerConeDeg = 40.0f;
    ConeCurve const c = sampleConeCurve(light, 101);
    ASSERT_EQ(c.degrees.size(), 101u);
    EXPECT_FLOAT_EQ(c.maxDegrees, 50.0f);  // a quarter past the outer angle
    for (std::size_t i = 0; i < c.degrees.size(); ++i) {
        float const a = c.degrees[i];
        EXPECT_EQ(c.factor[i], spotConeFactor(spotCone(light), std::cos(glm::radians(a))));
        if (a < 20.0f) {
            EXPECT_EQ(c.factor[i], 1.0f) << a;
        }
        if (a > 40.0f) {
            EXPECT_EQ(c.factor[i], 0.0f) << a;
        }
        if (i > 0) {
            EXPECT_LE(c.factor[i], c.factor[i - 1]);  // never brighter further off the axis
        }
    }
    EXPECT_GT(c.factor[60], 0.0f);  // 30 degrees: between inner and outer
    EXPECT_LT(c.factor[60], 1.0f);
}

// The ImPlot plot itself, drawn in a CPU-only ImGui context (no renderer: the frames are built,
// never drawn): what ImPlot holds after the plot is what the panel asked for.
namespace {
struct PlotRun {
    AttenuationPlotMarks marks;
    ImPlotRange x, y;  // the axes as ImPlot kept them after EndPlot
};

PlotRun drawPlotFrames(PointLight const& light, float fixedAxis, std::optional<float> pixel, PointLight const* ghost,
                       bool logScale = false) {
    ImGui::CreateContext();
    ImPlot::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(800, 600);
    io.IniFilename = nullptr;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // builds the atlas: text has sizes
    PlotRun run;
    for (int frame = 0; frame < 3; ++frame) {
        io.DeltaTime = 1.0f / 60.0f;
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(500, 400));
        ImGui::Begin("plot");
        run.marks = drawAttenuationPlot(light, logScale, ImVec2(400, 260), fixedAxis, pixel, ghost);
        ImPlotPlot const* plot = ImPlot::GetPlot("##attenuation");
        EXPECT_NE(plot, nullptr);
        if (plot) {
            run.x = plot->Axes[ImAxis_X1].Range;
            run.y = plot->Axes[ImAxis_Y1].Range;
        }
        ImGui::End();
        ImGui::Render();
    }
    ImPlot::DestroyContext();
    ImGui::DestroyContext();
    return run;
}
}  // namespace

TEST(UiAttenuationPlot, ImPlotGetsTheCurvesTheThresholdAndTheRadius) {
    PointLight light;
    float const r = lightRadius(light).radius;
    PlotRun const run = drawPlotFrames(light, 0.0f, std::nullopt, nullptr);
    EXPECT_FLOAT_EQ(run.marks.radius, r);
    EXPECT_EQ(run.marks.ghostRadius, -1.0f);
    // The distance axis a quarter past the radius; the intensity axis from 0 to 5 % over the peak
    // (Imax / Kc at d = 0, at least twice the threshold).
    EXPECT_NEAR(run.x.Min, 0.0, 1e-6);
    EXPECT_NEAR(run.x.Max, r * 1.25, 1e-4);
    EXPECT_FLOAT_EQ(run.marks.axisMax, float(run.x.Max));
    float const peak = std::max(lightImax(light) / light.kc, light.threshold * 2.0f);
    EXPECT_NEAR(run.y.Min, 0.0, 1e-6);
    EXPECT_NEAR(run.y.Max, peak * 1.05, 1e-4);
    // The threshold, the radius, the textbook curve and the applied one; only the curves in the legend.
    EXPECT_EQ(run.marks.items, 4);
    EXPECT_EQ(run.marks.legend, (std::vector<std::string>{"1/(Kc+Kl d+Kq d²)", "applied"}));
}

TEST(UiAttenuationPlot, ImPlotGetsTheGhostAndThePickedPixel) {
    PointLight light;
    PointLight ghost = light;
    ghost.kq = light.kq * 4.0f;  // a smaller radius before the drag
    float const r = lightRadius(light).radius, g = lightRadius(ghost).radius;
    ASSERT_LT(g, r);
    PlotRun const run = drawPlotFrames(light, 0.0f, 0.5f * r, &ghost);
    EXPECT_FLOAT_EQ(run.marks.radius, r);
    EXPECT_FLOAT_EQ(run.marks.ghostRadius, g);
    EXPECT_NEAR(run.x.Max, std::max(r, g) * 1.25, 1e-4);
    // Threshold, ghost radius, radius, pixel, the ghost curve, the textbook curve, the applied one.
    EXPECT_EQ(run.marks.items, 7);
    EXPECT_EQ(run.marks.legend, (std::vector<std::string>{"before the drag", "1/(Kc+Kl d+Kq d²)", "applied"}));
}

TEST(UiAttenuationPlot, AFixedAxisHoldsImPlotsAxisAndAFarPixelIsNoLine) {
    PointLight light;
    float const r = lightRadius(light).radius;
    // The axis held at half the radius: the radius and a pixel at 2 r lie past it, so neither is a
    // line (the pixel is then said in text at the axis' end).
    PlotRun const run = drawPlotFrames(light, 0.5f * r, 2.0f * r, nullptr);
    EXPECT_NEAR(run.x.Max, 0.5 * r, 1e-4);
    EXPECT_EQ(run.marks.items, 3);  // the threshold and the two curves
}

TEST(UiAttenuationPlot, ALogAxisStartsATenthBelowTheThreshold) {
    PointLight light;
    PlotRun const run = drawPlotFrames(light, 0.0f, std::nullopt, nullptr, true);
    EXPECT_NEAR(run.y.Min, light.threshold * 0.1, 1e-6);
    EXPECT_EQ(run.marks.items, 4);
}
