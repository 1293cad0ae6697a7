// Image statistics for the viewer tools.
#include "model/image_stats.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gbl::ui {

namespace {

bool skipped(FloatImage const& image, int x, int y, RangeSkip skip) {
    if (skip == RangeSkip::ZeroAlpha && image.channels == 4) return image.at(x, y, 3) == 0.0f;
    if (skip == RangeSkip::FarDepth) return image.at(x, y, 0) >= 1.0f;
    return false;
}

// Calls f(value) for each shown channel of each pixel that takes part, pixel by pixel: begin(x, y)
// before a pixel's values, end() after them.
template <class Begin, class Value, class End>
void forEachShown(FloatImage const& image, unsigned mask, std::optional<PixelRect> const& region, RangeSkip skip,
                  Begin begin, Value value, End end) {
    PixelRect const r = clampRect(region, image.width, image.height);
    int const channels = std::min(image.channels, 4);
    for (int y = r.min.y; y < r.max.y; ++y) {
        for (int x = r.min.x; x < r.max.x; ++x) {
            if (skipped(image, x, y, skip)) continue;
            begin(x, y);
            for (int c = 0; c < channels; ++c)
                if (mask & (1u << c)) value(c, image.at(x, y, c));
            end();
        }
    }
}

void add(ChannelStats& s, double& sum, float v) {
    if (std::isnan(v)) {
        ++s.nan;
        return;
    }
    if (std::isinf(v)) {
        ++s.inf;
        if (v < 0.0f) ++s.negative;
        return;
    }
    if (v < 0.0f) ++s.negative;
    if (s.finite == 0) s.min = s.max = v;
    s.min = std::min(s.min, v);
    s.max = std::max(s.max, v);
    sum += double(v);
    ++s.finite;
}

}  // namespace

PixelRect rectFromCorners(glm::ivec2 a, glm::ivec2 b) {
    return {glm::min(a, b), glm::max(a, b) + 1};
}

PixelRect clampRect(std::optional<PixelRect> const& r, int width, int height) {
    PixelRect const whole{{0, 0}, {std::max(width, 0), std::max(height, 0)}};
    if (!r || r->max.x <= r->min.x || r->max.y <= r->min.y) return whole;
    PixelRect c{glm::clamp(r->min, whole.min, whole.max), glm::clamp(r->max, whole.min, whole.max)};
    return c;
}

ImageStats imageStats(FloatImage const& image, unsigned channelMask, std::optional<PixelRect> region, RangeSkip skip) {
    ImageStats s;
    std::array<double, 4> sums{};
    double shownSum = 0.0;
    bool nan = false, inf = false, negative = false;
    forEachShown(
        image, channelMask, region, skip, [&](int, int) { nan = inf = negative = false; },
        [&](int c, float v) {
            add(s.channel[std::size_t(c)], sums[std::size_t(c)], v);
            add(s.shown, shownSum, v);
            nan |= std::isnan(v);
            inf |= std::isinf(v);
            negative |= v < 0.0f;
        },
        [&] {
            ++s.pixels;
            s.nanPixels += nan;
            s.infPixels += inf;
            s.negativePixels += negative;
        });
    for (std::size_t c = 0; c < 4; ++c)
        if (s.channel[c].finite > 0) s.channel[c].mean = sums[c] / double(s.channel[c].finite);
    if (s.shown.finite > 0) s.shown.mean = shownSum / double(s.shown.finite);
    return s;
}

long Histogram::maxBin() const {
    return bins.empty() ? 0 : *std::max_element(bins.begin(), bins.end());
}

Histogram histogram(FloatImage const& image, unsigned channelMask, float lo, float hi, int bins,
                    std::optional<PixelRect> region, RangeSkip skip) {
    Histogram h;
    h.lo = lo;
    h.hi = hi;
    h.bins.assign(std::size_t(std::max(bins, 1)), 0);
    double const scale = hi > lo ? double(h.bins.size()) / (double(hi) - double(lo)) : 0.0;
    forEachShown(
        image, channelMask, region, skip, [](int, int) {},
        [&](int, float v) {
            if (!std::isfinite(v)) return;
            if (v < lo)
                ++h.below;
            else if (v > hi)
                ++h.above;
            else {
                auto const i = std::size_t(std::floor((double(v) - double(lo)) * scale));
                ++h.bins[std::min(i, h.bins.size() - 1)];
            }
        },
        [] {});
    return h;
}

ValueRange percentileRange(FloatImage const& image, unsigned channelMask, float lowPercent, float highPercent,
                           std::optional<PixelRect> region, RangeSkip skip) {
    std::vector<float> values;
    forEachShown(
        image, channelMask, region, skip, [](int, int) {},
        [&](int, float v) {
            if (std::isfinite(v)) values.push_back(v);
        },
        [] {});
    if (values.empty()) return {};
    // Nearest rank: the p-th percentile of n sorted values is the ceil(p / 100 * n)-th (1-based).
    auto rank = [&](float percent) {
        double const p = std::clamp(double(percent), 0.0, 100.0);
        auto const k = std::size_t(std::max(std::ceil(p / 100.0 * double(values.size())), 1.0)) - 1;
        std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
        return values[k];
    };
    ValueRange r{rank(lowPercent), rank(highPercent), long(values.size())};
    if (r.max <= r.min) r.max = r.min + 1e-6f;  // a flat image still needs a non-empty range
    return r;
}

ClipCounts clipCounts(FloatImage const& image, unsigned channelMask, float black, float white,
                      std::optional<PixelRect> region, RangeSkip skip) {
    ClipCounts c;
    forEachShown(
        image, channelMask, region, skip, [](int, int) {},
        [&](int, float v) {
            if (!std::isfinite(v)) return;
            if (v < black)
                ++c.below;
            else if (v > white)
                ++c.above;
            else
                ++c.inside;
        },
        [] {});
    return c;
}

DiffStats diffImages(FloatImage const& current, FloatImage const& pinned, unsigned channelMask, float threshold,
                     DiffMode mode) {
    DiffStats d;
    if (current.width != pinned.width || current.height != pinned.height || current.channels != pinned.channels ||
        current.width <= 0 || current.height <= 0)
        return d;
    d.comparable = true;
    d.diff.width = current.width;
    d.diff.height = current.height;
    d.diff.channels = 1;
    d.diff.pixels.assign(std::size_t(current.width) * std::size_t(current.height), 0.0f);
    int const channels = std::min(current.channels, 4);
    double sum = 0.0;
    long finite = 0;
    for (int y = 0; y < current.height; ++y) {
        for (int x = 0; x < current.width; ++x) {
            float worst = 0.0f;
            bool bad = false;
            for (int c = 0; c < channels; ++c) {
                if (!(channelMask & (1u << c))) continue;
                float const a = current.at(x, y, c), b = pinned.at(x, y, c);
                if (!std::isfinite(a) || !std::isfinite(b)) {
                    bad = true;
                    continue;
                }
                float e = std::abs(a - b);
                if (mode == DiffMode::Relative) e /= std::max(std::abs(b), 1e-6f);
                worst = std::max(worst, e);
            }
            ++d.pixels;
            float& out = d.diff.pixels[std::size_t(y) * std::size_t(current.width) + std::size_t(x)];
            if (bad) {
                ++d.nanPixels;
                out = std::numeric_limits<float>::quiet_NaN();
                continue;
            }
            out = worst;
            sum += double(worst);
            ++finite;
            if (worst > threshold) ++d.overThreshold;
            if (d.maxAt.x < 0 || worst > d.max) {
                d.maxAt = {x, y};
                d.max = worst;
            }
        }
    }
    if (finite > 0) d.mean = sum / double(finite);
    return d;
}

}  // namespace gbl::ui
