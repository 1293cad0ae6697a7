// Per-pixel angle between two sets of decoded normals.
#include "model/normal_angle.h"

#include <cmath>
#include <limits>

namespace gbl::ui {

float angleDegrees(glm::vec3 a, glm::vec3 b) {
    float const la = glm::length(a), lb = glm::length(b);
    if (!(la > 0.0f) || !(lb > 0.0f) || !std::isfinite(la) || !std::isfinite(lb))
        return std::numeric_limits<float>::quiet_NaN();
    float const sine = glm::length(glm::cross(a, b)) / (la * lb);
    float const cosine = glm::dot(a, b) / (la * lb);
    return glm::degrees(std::atan2(sine, cosine));
}

DiffStats normalAngleDiff(FloatImage const& a, FloatImage const& b, float thresholdDegrees) {
    DiffStats d;
    if (a.width != b.width || a.height != b.height || a.channels < 4 || b.channels < 4 || a.width <= 0 || a.height <= 0)
        return d;
    d.comparable = true;
    d.diff.width = a.width;
    d.diff.height = a.height;
    d.diff.channels = 1;
    d.diff.pixels.assign(std::size_t(a.width) * std::size_t(a.height), 0.0f);
    double sum = 0.0;
    long finite = 0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            bool const drawnA = a.at(x, y, 3) > 0.0f, drawnB = b.at(x, y, 3) > 0.0f;
            if (!drawnA && !drawnB) continue;  // background on both sides
            ++d.pixels;
            float& out = d.diff.pixels[std::size_t(y) * std::size_t(a.width) + std::size_t(x)];
            float const angle = drawnA && drawnB ? angleDegrees({a.at(x, y, 0), a.at(x, y, 1), a.at(x, y, 2)},
                                                                {b.at(x, y, 0), b.at(x, y, 1), b.at(x, y, 2)})
                                                 : std::numeric_limits<float>::quiet_NaN();
            if (!std::isfinite(angle)) {
                ++d.nanPixels;
                out = std::numeric_limits<float>::quiet_NaN();
                continue;
            }
            out = angle;
            sum += double(angle);
            ++finite;
            if (angle > thresholdDegrees) ++d.overThreshold;
            if (d.maxAt.x < 0 || angle > d.max) {
                d.maxAt = {x, y};
                d.max = angle;
            }
        }
    }
    d.mean = finite > 0 ? sum / double(finite) : 0.0;
    return d;
}

}  // namespace gbl::ui
