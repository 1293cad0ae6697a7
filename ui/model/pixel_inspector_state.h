// State of the pixel inspector: the pixel, its stored values and its per-light breakdown.
#pragma once

#include "core/frame_types.h"
#include "core/pipeline_settings.h"
#include "core/shading_cpu.h"
#include "model/msaa_views.h"
#include "model/why_value.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gbl::ui {

// Each light's share of the lit value at one pixel, from the CPU copy of the shader's math.
struct PixelBreakdown {
    glm::vec3 ambient{0.0f};                     // ambient * albedo * occlusion + emissive
    std::vector<gbl::LightContribution> lights;  // only lights that reach the pixel, brightest first
    glm::vec3 total{0.0f};                       // ambient + sum of the lights
    int lightsTested = 0;
    // Every light, in list order: did the current mode evaluate it here, why, what it added
    // (model/why_value.h). Empty when the breakdown was made without the frame's geometry.
    std::vector<LightVerdict> verdicts;
};

struct PixelInspectorState {
    bool locked = false;                // keep showing the pixel after the mouse leaves
    std::optional<glm::ivec2> pixel;    // top-left origin, renderer pixels
    std::string source;                 // where the mouse was: "viewport" or a viewer's name
    std::optional<PixelSample> sample;  // read by Renderer::samplePixel after the frame
    std::optional<PixelBreakdown> breakdown;
    std::string breakdownNote;  // why there is no breakdown, when there is none
    PipelineSettings settings;  // the sampled frame's (its ambient is 0 for a light's contribution)
    int selectLight = -1;       // a light row was clicked: the loop selects it
    bool everyLight = false;    // list every light, not only those within reach
    // An open G-buffer's own lit image at the pixel (its manifest's "lit", pinned in the viewport),
    // shown beside our stored value and per-light sum.
    std::optional<glm::vec3> theirs;
    // msaa (issue 47): the sample listed, -1 for every one, and the pixel's samples decoded as the
    // lighting reads them (read by the loop while the frame shown ran msaa; empty otherwise).
    int msaaSample = -1;
    std::vector<MsaaPixelSample> msaaSamples;
};

}  // namespace gbl::ui
