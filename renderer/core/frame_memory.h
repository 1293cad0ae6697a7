// The screen-sized memory each lighting mode's frame writes, per pixel, from the targets its passes
// declare: the G-buffer (deferred modes only), the lit image and its depth, and the tiles' light
// lists where the mode bins them. What the Stats window and stats.json report as bytes a pixel.
#pragma once

#include "core/gbuffer_layout.h"
#include "core/pipeline_settings.h"

#include <string>
#include <vector>

namespace gbl {

struct MemoryPart {
    std::string name;
    double bytesPerPixel = 0.0;

    bool operator==(MemoryPart const&) const = default;
};

struct FrameMemory {
    bool gbuffer = false;  // false: forward and forward+, which write no G-buffer
    std::vector<MemoryPart> parts;

    double bytesPerPixel() const {
        double sum = 0.0;
        for (MemoryPart const& p : parts) sum += p.bytesPerPixel;
        return sum;
    }
};

// The per-pixel share of the tiles' lists (passes/tile_bins.h: a count, a depth range and `cap`
// light indices per 16x16 tile), at width x height with the storage-block limit that caps a list.
double tileListBytesPerPixel(int width, int height, long long maxStorageBlockBytes);

// Counted: the G-buffer's attachments (deferred modes), the lit image (RGBA16F), the lit target's
// depth-stencil (the depth pre-pass's in forward+, the depth-copy's in the deferred modes), and the
// opaque surfaces' tile lists (tiled, forward+). Not counted: what every mode allocates for the
// views (display image, coverage counts, split light targets), clustered's cluster lists, and
// forward+'s second set of lists for blended surfaces (binned only when the scene has some).
FrameMemory frameMemory(LightingMode mode, GBufferLayoutDesc const& layout, int width, int height,
                        long long maxStorageBlockBytes);

}  // namespace gbl
