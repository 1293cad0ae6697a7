// What the viewport draws over its image (panel_viewport.cpp): the heat-map and slice legends'
// words, boxed notes, and the A/B split's and diff's labels and divider. ImGui draw lists only.
#pragma once

#include "core/pipeline_settings.h"
#include "panels/panel_viewport.h"

#include <imgui.h>
#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace gbl::ui {

// The heat-map views' legend words over the bar the shader draws (kHeatBins swatches); nothing
// below 64x64 texels, where the shader draws no bar either.
void labelHeatLegend(ImVec2 imageMin, ImVec2 imageMax, glm::ivec2 textureSize, DebugView view, LightingMode mode);
// How far above the image's bottom that legend and its labels reach (0: none drawn at this size).
float heatLegendHeight(ImVec2 imageMin, ImVec2 imageMax, glm::ivec2 textureSize);
// The cluster-slice view's legend: each slice band's depth range.
void labelSliceLegend(ImVec2 imageMin, ImVec2 imageMax, glm::ivec2 textureSize, glm::vec2 clip);
// Text with a dark box behind it, so it reads over any frame.
void boxedText(ImVec2 p, std::string const& text);
// One side's GPU ms per pass, as much as fits in `width` pixels.
std::string passLine(char const* side, std::vector<PassTiming> const& passes, double total, float width);
// "A: volumes/front".
std::string sideLabel(char const* side, PipelineSettings const& s);
// The A/B divider, dragged with the left button; submitted before the image's own button.
void abDivider(AbState& ab, ImVec2 origin, ImVec2 avail);
// The A/B split's and diff's labels over the image.
// bottomInset: room kept free at the bottom of the image (a heat legend's), above which the pass
// lines sit.
void drawAbSplit(ViewportTeaching const& v, PipelineSettings const& a, ImVec2 origin, ImVec2 avail,
                 float bottomInset = 0.0f);
void drawAbDiff(ViewportTeaching const& v, PipelineSettings const& a, ImVec2 origin, ImVec2 avail);

}  // namespace gbl::ui
