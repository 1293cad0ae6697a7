// Colormap tables and legend ticks.
#include "model/colormap.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace gbl::ui {

namespace {

// 33 evenly spaced stops each, interpolated linearly. Sampled (and rounded to 3 decimals) by us from
// the published polynomial approximations of the two maps: turbo (Google's rainbow replacement,
// 2019) and viridis (matplotlib's default, 2015). Linear interpolation between stops stays within
// 4/255 of those polynomials.
constexpr int kStops = 33;
constexpr std::array<glm::vec3, kStops> kTurbo{{
    {0.136f, 0.091f, 0.107f}, {0.242f, 0.164f, 0.446f}, {0.288f, 0.244f, 0.686f}, {0.291f, 0.328f, 0.844f},
    {0.269f, 0.415f, 0.935f}, {0.234f, 0.501f, 0.973f}, {0.197f, 0.586f, 0.970f}, {0.167f, 0.666f, 0.936f},
    {0.148f, 0.740f, 0.881f}, {0.146f, 0.808f, 0.811f}, {0.162f, 0.866f, 0.733f}, {0.197f, 0.915f, 0.653f},
    {0.250f, 0.953f, 0.573f}, {0.319f, 0.979f, 0.497f}, {0.401f, 0.993f, 0.428f}, {0.492f, 0.994f, 0.367f},
    {0.589f, 0.982f, 0.313f}, {0.685f, 0.958f, 0.268f}, {0.777f, 0.921f, 0.231f}, {0.861f, 0.873f, 0.201f},
    {0.932f, 0.814f, 0.177f}, {0.985f, 0.746f, 0.158f}, {1.000f, 0.670f, 0.142f}, {1.000f, 0.588f, 0.128f},
    {1.000f, 0.502f, 0.114f}, {0.988f, 0.415f, 0.100f}, {0.935f, 0.329f, 0.084f}, {0.866f, 0.248f, 0.067f},
    {0.786f, 0.175f, 0.047f}, {0.705f, 0.114f, 0.027f}, {0.632f, 0.070f, 0.006f}, {0.580f, 0.047f, 0.000f},
    {0.566f, 0.050f, 0.000f},
}};
constexpr std::array<glm::vec3, kStops> kViridis{{
    {0.278f, 0.005f, 0.334f}, {0.281f, 0.049f, 0.377f}, {0.282f, 0.093f, 0.417f}, {0.281f, 0.135f, 0.453f},
    {0.278f, 0.176f, 0.483f}, {0.272f, 0.215f, 0.507f}, {0.264f, 0.253f, 0.526f}, {0.252f, 0.288f, 0.539f},
    {0.239f, 0.322f, 0.548f}, {0.223f, 0.355f, 0.554f}, {0.205f, 0.387f, 0.556f}, {0.187f, 0.418f, 0.557f},
    {0.170f, 0.448f, 0.557f}, {0.153f, 0.478f, 0.555f}, {0.139f, 0.507f, 0.553f}, {0.128f, 0.537f, 0.550f},
    {0.122f, 0.566f, 0.546f}, {0.121f, 0.595f, 0.540f}, {0.128f, 0.624f, 0.531f}, {0.142f, 0.653f, 0.519f},
    {0.165f, 0.681f, 0.503f}, {0.197f, 0.709f, 0.482f}, {0.239f, 0.736f, 0.455f}, {0.291f, 0.761f, 0.421f},
    {0.352f, 0.785f, 0.382f}, {0.423f, 0.807f, 0.337f}, {0.501f, 0.827f, 0.288f}, {0.585f, 0.845f, 0.236f},
    {0.673f, 0.861f, 0.187f}, {0.762f, 0.875f, 0.144f}, {0.847f, 0.886f, 0.114f}, {0.924f, 0.897f, 0.107f},
    {0.987f, 0.906f, 0.131f},
}};

glm::vec3 sampleStops(std::array<glm::vec3, kStops> const& stops, float t) {
    float const p = t * float(kStops - 1);
    int const i = std::min(int(p), kStops - 2);
    return glm::mix(stops[std::size_t(i)], stops[std::size_t(i) + 1], p - float(i));
}

}  // namespace

glm::vec3 colormap(Colormap map, float t) {
    t = std::isnan(t) ? 0.0f : std::clamp(t, 0.0f, 1.0f);
    switch (map) {
        case Colormap::Grey:
            return glm::vec3(t);
        case Colormap::Turbo:
            return sampleStops(kTurbo, t);
        case Colormap::Viridis:
            return sampleStops(kViridis, t);
    }
    return glm::vec3(t);
}

std::vector<LegendTick> legendTicks(float lo, float hi, int target) {
    std::vector<LegendTick> ticks;
    if (!std::isfinite(lo) || !std::isfinite(hi) || hi <= lo || target < 1) return ticks;
    // Pick the smallest round step that gives at most `target` intervals.
    double const raw = (double(hi) - double(lo)) / double(target);
    double const power = std::pow(10.0, std::floor(std::log10(raw)));
    double step = power * 10.0;
    for (double m : {1.0, 2.0, 5.0, 10.0}) {
        if (power * m >= raw) {
            step = power * m;
            break;
        }
    }
    double const first = std::ceil(double(lo) / step - 1e-9) * step;
    for (int i = 0;; ++i) {
        double v = first + double(i) * step;
        if (v > double(hi) + step * 1e-9) break;
        if (std::abs(v) < step * 1e-9) v = 0.0;  // no "-0" or 1e-17 from accumulated rounding
        ticks.push_back({float(v), float((v - double(lo)) / (double(hi) - double(lo)))});
    }
    return ticks;
}

}  // namespace gbl::ui
