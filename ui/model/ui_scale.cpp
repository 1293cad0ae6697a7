// Parsing and writing the UI scale.
#include "model/ui_scale.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace gbl::ui {

std::optional<float> parseUiScale(std::string_view text, std::string_view what, std::string* error) {
    std::string const s(text);
    char* end = nullptr;
    float const value = s.empty() ? 0.0f : std::strtof(s.c_str(), &end);
    bool const number = !s.empty() && end == s.c_str() + s.size() && std::isfinite(value);
    if (number && value >= kUiScaleMin && value <= kUiScaleMax) return value;
    if (error) {
        char range[64];
        std::snprintf(range, sizeof range, "between %g and %g", double(kUiScaleMin), double(kUiScaleMax));
        *error = std::string(what) + " must be a number " + range + " (1.5 for a projector), got '" + s + "'";
    }
    return std::nullopt;
}

float scaledPixels(float pixels, float scale) {
    return std::floor(pixels * scale);
}

std::string uiScaleText(float scale) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(scale));
    return text;
}

std::string uiScaleLine(float scale) {
    return std::string(kUiScaleKey) + "=" + uiScaleText(scale);
}

}  // namespace gbl::ui
