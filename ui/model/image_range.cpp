// Value ranges of read-back attachments.
#include "model/image_range.h"

#include "core/depth.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gbl::ui {

ValueRange fitRange(FloatImage const& image, unsigned channelMask, RangeSkip skip, bool linearize, float nearPlane,
                    float farPlane) {
    float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
    long n = 0;
    int const channels = image.channels;
    if (channels <= 0) return {};
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            if (skip == RangeSkip::ZeroAlpha && channels == 4 && image.at(x, y, 3) == 0.0f) continue;
            if (skip == RangeSkip::FarDepth && image.at(x, y, 0) >= 1.0f) continue;
            for (int c = 0; c < channels; ++c) {
                if (!(channelMask & (1u << c))) continue;
                float v = image.at(x, y, c);
                if (linearize) v = linearDepth(v, nearPlane, farPlane);
                if (!std::isfinite(v)) continue;
                lo = std::min(lo, v);
                hi = std::max(hi, v);
                ++n;
            }
        }
    }
    if (n == 0) return {};
    if (hi <= lo) hi = lo + 1e-6f;  // a flat image still needs a non-empty range
    return {lo, hi, n};
}

}  // namespace gbl::ui
