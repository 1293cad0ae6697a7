// Statistics of read-back images for the viewer tools: histogram, min/max/mean, NaN/Inf/negative
// counts, percentile fits, clipping counts, region statistics and the difference of two images.
// Pure functions over FloatImage; no GL.
#pragma once

#include "core/frame_types.h"
#include "model/image_range.h"

#include <glm/glm.hpp>

#include <array>
#include <optional>
#include <vector>

namespace gbl::ui {

// Texel rectangle, min inclusive, max exclusive, top-left origin (as the viewers report texels).
struct PixelRect {
    glm::ivec2 min{0};
    glm::ivec2 max{0};
    bool operator==(PixelRect const&) const = default;
};

// The rectangle spanned by two texels given in any order, both included.
PixelRect rectFromCorners(glm::ivec2 a, glm::ivec2 b);
// r clipped to the image; the whole image when r is empty.
PixelRect clampRect(std::optional<PixelRect> const& r, int width, int height);

struct ChannelStats {
    float min = 0.0f;  // over finite values; 0 when there are none
    float max = 0.0f;
    double mean = 0.0;
    long finite = 0;  // finite values counted
    long nan = 0;
    long inf = 0;       // +Inf and -Inf
    long negative = 0;  // finite values below 0, and -Inf
};

struct ImageStats {
    std::array<ChannelStats, 4> channel{};  // per channel; only those in the mask are filled
    ChannelStats shown;                     // over every channel in the mask together
    long pixels = 0;                        // pixels that took part (after the skip rule)
    // Pixels with at least one shown channel NaN / Inf / negative: what the overlays mark.
    long nanPixels = 0;
    long infPixels = 0;
    long negativePixels = 0;
};

// Statistics of the channels in channelMask (bit 0 = R ...) inside region (whole image if none).
ImageStats imageStats(FloatImage const& image, unsigned channelMask, std::optional<PixelRect> region = {},
                      RangeSkip skip = RangeSkip::None);

struct Histogram {
    float lo = 0.0f;
    float hi = 1.0f;
    std::vector<long> bins;  // finite values in [lo, hi]; hi itself falls in the last bin
    long below = 0;          // finite values < lo
    long above = 0;          // finite values > hi
    long maxBin() const;
};

// Histogram of the finite values of the shown channels over [lo, hi] in `bins` equal bins.
Histogram histogram(FloatImage const& image, unsigned channelMask, float lo, float hi, int bins,
                    std::optional<PixelRect> region = {}, RangeSkip skip = RangeSkip::None);

// The range from the lowPercent-th to the highPercent-th percentile (nearest rank) of the finite
// values of the shown channels: the auto-fit that ignores NaN, Inf and outliers.
ValueRange percentileRange(FloatImage const& image, unsigned channelMask, float lowPercent, float highPercent,
                           std::optional<PixelRect> region = {}, RangeSkip skip = RangeSkip::None);

struct ClipCounts {
    long below = 0;  // finite shown values below the black point
    long above = 0;  // finite shown values above the white point
    long inside = 0;
};
ClipCounts clipCounts(FloatImage const& image, unsigned channelMask, float black, float white,
                      std::optional<PixelRect> region = {}, RangeSkip skip = RangeSkip::None);

// --- pin & diff ----------------------------------------------------------------------------------

enum class DiffMode { Absolute, Relative };  // |a - b|, or |a - b| / max(|b|, 1e-6) with b the pinned image

struct DiffStats {
    bool comparable = false;  // same size and channel count; nothing else is filled otherwise
    FloatImage diff;          // one channel: the largest difference over the shown channels
    float max = 0.0f;         // largest finite difference
    glm::ivec2 maxAt{-1};     // first texel (row-major) holding it; -1 when no finite difference
    double mean = 0.0;        // over pixels with a finite difference
    long overThreshold = 0;   // pixels whose difference is > threshold
    long nanPixels = 0;       // pixels where a shown channel of either image is NaN or Inf
    long pixels = 0;
};

DiffStats diffImages(FloatImage const& current, FloatImage const& pinned, unsigned channelMask, float threshold,
                     DiffMode mode = DiffMode::Absolute);

}  // namespace gbl::ui
