// Lesson text placeholders: validation and substitution.
#include "model/lesson_text.h"

#include "core/gbuffer_layout.h"
#include "core/light_math.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gbl::ui {

namespace {

std::string vec3Text(glm::vec3 v) {
    return "(" + lessonNumber(v.x) + ", " + lessonNumber(v.y) + ", " + lessonNumber(v.z) + ")";
}

bool known(std::string_view name) {
    return std::find(kLessonPlaceholders.begin(), kLessonPlaceholders.end(), name) != kLessonPlaceholders.end();
}

std::string value(std::string_view name, LessonValues const& v) {
    std::string const na = "n/a";
    if (name == "lights.count") return std::to_string(v.lightCount);
    if (name == "pipeline.mode") return std::string(enumName(kLightingModeNames, v.pipeline.mode));
    if (name.starts_with("frame.")) {
        if (v.frameSize.x <= 0 || v.frameSize.y <= 0) return na;
        long long const pixels = (long long)v.frameSize.x * v.frameSize.y;
        if (name == "frame.width") return std::to_string(v.frameSize.x);
        if (name == "frame.height") return std::to_string(v.frameSize.y);
        if (name == "frame.pixels") return std::to_string(pixels);
        if (name == "frame.evaluations") return std::to_string(pixels * v.lightCount);
        if (name == "frame.gbuffer_mb")
            return lessonNumber(float(layoutMegabytes(layoutDesc(v.pipeline.layout), v.frameSize.x, v.frameSize.y)));
    }
    if (name == "pipeline.cull") return std::string(enumName(kCullModeNames, v.pipeline.cull));
    if (name.starts_with("light.")) {
        if (!v.light) return na;
        PointLight const& l = *v.light;
        if (name == "light.index") return std::to_string(v.lightIndex);
        if (name == "light.name") return l.name.empty() ? "light " + std::to_string(v.lightIndex) : l.name;
        if (name == "light.kc") return lessonNumber(l.kc);
        if (name == "light.kl") return lessonNumber(l.kl);
        if (name == "light.kq") return lessonNumber(l.kq);
        if (name == "light.intensity") return lessonNumber(l.intensity);
        if (name == "light.threshold") return lessonNumber(l.threshold);
        if (name == "light.imax") return lessonNumber(lightImax(l));
        if (name == "light.imax_256_5") return lessonNumber(lightImax(l) / l.threshold);
        if (name == "light.radius") return lessonNumber(lightRadius(l).radius);
    }
    if (name == "pixel.x") return v.pixel ? std::to_string(v.pixel->x) : na;
    if (name == "pixel.y") return v.pixel ? std::to_string(v.pixel->y) : na;
    if (!v.sample) return na;
    PixelSample const& s = *v.sample;
    if (name == "pixel.lit") return vec3Text(glm::vec3(s.lighting));
    if (name == "pixel.depth") return lessonNumber(s.depth);
    // The heat map's or tile view's counts at the pixel: lights evaluated, lights that reached it.
    if (name == "pixel.evaluated" || name == "pixel.reached") {
        if (!s.coverageView) return na;
        return std::to_string(int(std::lround(name == "pixel.evaluated" ? s.coverage.x : s.coverage.y)));
    }
    if (!s.covered) return "(no geometry)";
    if (name == "pixel.position") return vec3Text(glm::vec3(s.position));
    if (name == "pixel.normal") return vec3Text(glm::vec3(s.normal));
    if (name == "pixel.error") return lessonNumber(glm::length(glm::vec3(s.position) - s.reconstructedPosition));
    return na;
}

}  // namespace

std::optional<std::string> unknownPlaceholder(std::string_view text) {
    for (std::size_t i = text.find('{'); i != std::string_view::npos; i = text.find('{', i + 1)) {
        std::size_t const close = text.find('}', i);
        if (close == std::string_view::npos) return std::string(text.substr(i));
        std::string_view const name = text.substr(i + 1, close - i - 1);
        if (!known(name)) return "{" + std::string(name) + "}";
    }
    return std::nullopt;
}

std::string substituteLessonText(std::string_view text, LessonValues const& values) {
    std::string out;
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t const open = text.find('{', pos);
        std::size_t const close = open == std::string_view::npos ? open : text.find('}', open);
        if (close == std::string_view::npos) break;
        std::string_view const name = text.substr(open + 1, close - open - 1);
        out += text.substr(pos, open - pos);
        out += known(name) ? value(name, values) : std::string(text.substr(open, close - open + 1));
        pos = close + 1;
    }
    out += text.substr(std::min(pos, text.size()));
    return out;
}

}  // namespace gbl::ui
