// Plot of a light's brightness against distance, with its threshold and radius, drawn from the
// same functions the renderer uses (gbl::attenuation, gbl::windowedAttenuation, gbl::lightRadius).
#pragma once

#include "core/point_light.h"

#include <imgui.h>

#include <optional>
#include <string>
#include <vector>

namespace gbl::ui {

struct AttenuationCurve {
    float maxDistance = 1.0f;
    float radius = 0.0f;
    std::vector<float> distance;
    std::vector<float> classic;  // Imax / (Kc + Kl d + Kq d^2)
    std::vector<float> applied;  // Imax * windowedAttenuation: what every lighting mode adds
};

// Samples both curves from 0 to a little past the radius, or to maxDistance when it is above 0
// (a fixed axis).
AttenuationCurve sampleAttenuationCurve(PointLight const& light, int samples, float maxDistance = 0.0f);

// What drawAttenuationPlot marked: the light's radius and its ghost's (-1 without a ghost), and the
// axes' ends as ImPlot holds them (0 when the plot was not drawn).
struct AttenuationPlotMarks {
    float radius = 0.0f;
    float ghostRadius = -1.0f;
    float axisMax = 0.0f;   // the distance axis' end
    float valueMax = 0.0f;  // the intensity axis' top
    // As ImPlot holds them at the end of the plot: its legend's entries in order, and how many
    // items (curves and marked lines) it was given this frame.
    std::vector<std::string> legend;
    int items = 0;
};

// Draws an ImPlot plot of `size` at the cursor (distance on x, intensity on y; the caller's last
// item is then the whole plot), inside an ImPlot context; hovering shows the values there.
// fixedMaxDistance > 0 holds the distance axis there instead of a quarter past the radius;
// pixelDistance (the inspected pixel's distance from the light) is marked where it is on the axis,
// or said at the axis' end when past it; the threshold and the radius are marked lines.
// ghost (the light before the current drag) is drawn faint behind, its radius marked too and
// "r = OLD → NEW" beside the radius; a following axis then reaches past both radii.
AttenuationPlotMarks drawAttenuationPlot(PointLight const& light, bool logScale, ImVec2 size,
                                         float fixedMaxDistance = 0.0f,
                                         std::optional<float> pixelDistance = std::nullopt,
                                         PointLight const* ghost = nullptr);

// The distance axis the plot uses: fixedMaxDistance when above 0, else a quarter past the larger
// of the light's and the ghost's radius (0 = sampleAttenuationCurve's own choice).
float attenuationPlotAxis(PointLight const& light, float fixedMaxDistance, PointLight const* ghost);

// A spot's cone factor (gbl::spotConeFactor) against the angle from its axis, 0 to a little
// past the outer angle, with the inner and outer angles marked.
struct ConeCurve {
    float maxDegrees = 1.0f;
    std::vector<float> degrees;
    std::vector<float> factor;
};
ConeCurve sampleConeCurve(PointLight const& light, int samples);
void drawConePlot(PointLight const& light, ImVec2 size);

}  // namespace gbl::ui
