// Pixel inspector window: exact stored values at the hovered pixel from every attachment, the
// position rebuilt from depth, and each light's share of the lit value.
#pragma once

#include "renderer.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gbl::ui {

// One light's part of the lit value at a pixel, evaluated on the CPU with the shader's math.
struct LightContribution {
    int light = -1;
    float distance = 0.0f;
    float attenuation = 0.0f;   // windowed attenuation actually applied
    glm::vec3 diffuse{0.0f};
    glm::vec3 specular{0.0f};
};

struct PixelBreakdown {
    glm::vec3 ambient{0.0f};
    std::vector<LightContribution> lights;  // only lights that reach the pixel, brightest first
    glm::vec3 total{0.0f};                  // ambient + sum of the lights
    int lightsTested = 0;
};

struct PixelInspectorState {
    bool locked = false;                // keep showing the pixel after the mouse leaves
    std::optional<glm::ivec2> pixel;    // top-left origin, renderer pixels
    std::string source;                 // where the mouse was: "viewport" or a viewer's name
    std::optional<PixelSample> sample;  // read by Renderer::samplePixel after the frame
    std::optional<PixelBreakdown> breakdown;
    std::string breakdownNote;          // why there is no breakdown, when there is none
    int selectLight = -1;               // a light row was clicked: the loop selects it
};

void drawPixelInspectorPanel(PixelInspectorState& state);

}  // namespace gbl::ui
