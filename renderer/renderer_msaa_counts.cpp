// msaa (docs/msaa.md): the samples-that-differ count of every pixel, from the multisampled
// G-buffer's samples read back in bands (core/msaa_samples.h counts them).
#include "renderer.h"

#include "core/msaa_samples.h"

#include <algorithm>
#include <array>
#include <vector>

namespace gbl {

FloatImage Renderer::msaaDistinctSampleCounts(glm::vec3 eye) {
    int const n = msaaSampleCount(), w = width(), h = height();
    if (n <= 0 || w <= 0 || h <= 0) return {};
    FloatImage counts{w, h, 1, std::vector<float>(std::size_t(w) * std::size_t(h), 0.0f)};
    constexpr int kBandRows = 64;  // 1280 wide, 8 samples, 3 slots: 31 MB of floats per band
    constexpr std::array<GBufferSlot, 3> kSlots{GBufferSlot::Position, GBufferSlot::Normal, GBufferSlot::AlbedoSpec};
    std::vector<MsaaSampleValues> pixel(static_cast<std::size_t>(n));
    for (int y0 = 0; y0 < h; y0 += kBandRows) {
        int const rows = std::min(kBandRows, h - y0);
        // band[slot][sample]: that sample of the band's pixels, RGBA.
        std::array<std::vector<FloatImage>, 3> band;
        for (std::size_t s = 0; s < kSlots.size(); ++s)
            for (int k = 0; k < n; ++k) {
                band[s].push_back(readMsaaSample(kSlots[s], k, {0, y0, w, rows}));
                if (band[s].back().pixels.size() != std::size_t(w) * std::size_t(rows) * 4) return {};
            }
        for (int y = 0; y < rows; ++y)
            for (int x = 0; x < w; ++x) {
                std::size_t const i = (std::size_t(y) * std::size_t(w) + std::size_t(x)) * 4;
                auto const at = [&](std::size_t s, int k) {
                    float const* p = band[s][std::size_t(k)].pixels.data() + i;
                    return glm::vec4(p[0], p[1], p[2], p[3]);
                };
                for (int k = 0; k < n; ++k) pixel[std::size_t(k)] = {at(0, k), at(1, k), at(2, k)};
                counts.pixels[std::size_t(y0 + y) * std::size_t(w) + std::size_t(x)] =
                    float(msaaDistinctSamples(pixel, eye));
            }
    }
    return counts;
}

}  // namespace gbl
