// The MSAA views' pictures and labels (msaa_views.h).
#include "model/msaa_views.h"

#include "core/heat_scale.h"

namespace gbl::ui {

std::vector<std::uint8_t> complexOverlayRgba(FloatImage const& mask) {
    std::size_t const n = std::size_t(mask.width) * std::size_t(mask.height);
    std::vector<std::uint8_t> rgba(n * 4, 0);
    if (mask.channels < 1 || mask.pixels.size() < n * std::size_t(mask.channels)) return rgba;
    for (std::size_t i = 0; i < n; ++i)
        if (mask.pixels[i * std::size_t(mask.channels)] > 0.5f) {
            rgba[i * 4 + 0] = 255;
            rgba[i * 4 + 1] = 0;
            rgba[i * 4 + 2] = 255;
            rgba[i * 4 + 3] = 200;  // the surface still shows through, the edge reads as magenta
        }
    return rgba;
}

FloatImage complexFromCounts(FloatImage const& counts) {
    FloatImage mask{counts.width, counts.height, 1, std::vector<float>(counts.pixels.size(), 0.0f)};
    for (std::size_t i = 0; i < counts.pixels.size(); ++i) mask.pixels[i] = counts.pixels[i] >= 2.0f ? 1.0f : 0.0f;
    return mask;
}

double maskShare(FloatImage const& mask) {
    if (mask.pixels.empty() || mask.channels < 1) return 0.0;
    std::size_t const n = mask.pixels.size() / std::size_t(mask.channels);
    std::size_t on = 0;
    for (std::size_t i = 0; i < n; ++i) on += mask.pixels[i * std::size_t(mask.channels)] > 0.5f ? 1 : 0;
    return double(on) / double(n);
}

std::vector<std::uint8_t> samplesHeatRgba(FloatImage const& counts) {
    std::size_t const n = std::size_t(counts.width) * std::size_t(counts.height);
    std::vector<std::uint8_t> rgba(n * 4, 255);
    for (std::size_t i = 0; i < n && i < counts.pixels.size(); ++i) {
        auto const& c = kHeatBinColors[std::size_t(heatBin(counts.pixels[i]))];
        for (int k = 0; k < 3; ++k) rgba[i * 4 + std::size_t(k)] = std::uint8_t(c[std::size_t(k)]);
    }
    return rgba;
}

std::optional<GBufferSlot> viewerSampleSlot(ViewerKind kind) {
    switch (kind) {
        case ViewerKind::Position:
            return GBufferSlot::Position;
        case ViewerKind::Normal:
            return GBufferSlot::Normal;
        case ViewerKind::Albedo:
        case ViewerKind::Specular:
            return GBufferSlot::AlbedoSpec;
        case ViewerKind::Depth:
        case ViewerKind::Lighting:
            return std::nullopt;
    }
    return std::nullopt;
}

std::string sampleChoiceLabel(int sample) {
    return sample < 0 ? std::string("all") : "sample " + std::to_string(sample);
}

int clampSample(int sample, int samples) {
    return sample >= 0 && sample < samples ? sample : -1;
}

}  // namespace gbl::ui
