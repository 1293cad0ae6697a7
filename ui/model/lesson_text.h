// The {placeholders} of lesson text and their live values: the selected light's numbers and the
// lesson pixel's stored and lit values, substituted into the text the Lessons window shows.
#pragma once

#include "core/frame_types.h"
#include "core/pipeline_settings.h"
#include "core/point_light.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

namespace gbl::ui {

// v with four significant digits, as lesson text and the claims' details print numbers.
inline std::string lessonNumber(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", double(v));
    return buf;
}

// Every placeholder a lesson may use, once: validation refuses others, substitution fills these.
inline constexpr std::array<std::string_view, 27> kLessonPlaceholders{
    "light.index",      "light.name",      "light.kc",     "light.kl",         "light.kq",     "light.intensity",
    "light.threshold",  "light.imax",      "light.radius", "light.imax_256_5", "pixel.x",      "pixel.y",
    "pixel.lit",        "pixel.depth",     "pixel.error",  "pixel.position",   "pixel.normal", "pipeline.mode",
    "pipeline.cull",    "lights.count",    "frame.width",  "frame.height",     "frame.pixels", "frame.evaluations",
    "frame.gbuffer_mb", "pixel.evaluated", "pixel.reached"};

// What the placeholders are filled from; missing values read "n/a".
struct LessonValues {
    std::optional<PointLight> light;  // the selected light
    int lightIndex = -1;
    std::optional<glm::ivec2> pixel;
    std::optional<PixelSample> sample;  // the inspector's read-back at that pixel
    PipelineSettings pipeline;
    int lightCount = 0;
    glm::ivec2 frameSize{0};  // the live frame (viewport) size; 0 = unknown
};

// The first placeholder in `text` that is not in kLessonPlaceholders (or an unclosed "{"), as
// written; nullopt when every one is known.
std::optional<std::string> unknownPlaceholder(std::string_view text);

// `text` with every known placeholder replaced by its value (numbers with 4 significant digits).
std::string substituteLessonText(std::string_view text, LessonValues const& values);

}  // namespace gbl::ui
