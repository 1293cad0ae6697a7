// Per-pixel memory of each lighting mode's frame.
#include "core/frame_memory.h"

#include "core/tile_math.h"

namespace gbl {

double tileListBytesPerPixel(int width, int height, long long maxStorageBlockBytes) {
    TileGrid const g = tileGrid(width, height);
    if (g.count() == 0) return 0.0;
    int const cap = tileBinCap(g.count(), maxStorageBlockBytes);
    double const perTile = 4.0 + 8.0 + 4.0 * double(cap);  // count, depth range, indices
    return perTile * double(g.count()) / (double(width) * double(height));
}

FrameMemory frameMemory(LightingMode mode, GBufferLayoutDesc const& d, int width, int height,
                        long long maxStorageBlockBytes) {
    FrameMemory m;
    m.gbuffer = !shadesForward(mode);
    double const depth = texelBytes(d.depthFormat());
    std::string const depthFormat(texelFormatName(d.depthFormat()));
    // prepass (docs/deferred_lighting.md) writes none of the layout's attachments: a thin G-buffer with
    // the lit target's depth, which its second geometry pass tests against (no depth copy).
    bool const prepass = mode == LightingMode::Prepass;
    if (prepass) {
        m.gbuffer = false;
        m.parts.push_back({"thin G-buffer RGBA16F (normal, exponent)", double(texelBytes(TexelFormat::RGBA16F))});
        m.parts.push_back({"thin depth " + depthFormat, depth});
        m.parts.push_back({"light targets 2 x RGBA16F", double(kPrepassLightBytesPerPixel)});
    }
    if (m.gbuffer) m.parts.push_back({"G-buffer (" + std::string(d.name) + ")", double(layoutBytesPerPixel(d))});
    if (mode == LightingMode::ForwardPlus) m.parts.push_back({"depth pre-pass " + depthFormat, depth});
    m.parts.push_back({"lit image RGBA16F", 8.0});
    if (mode == LightingMode::Forward) m.parts.push_back({"depth " + depthFormat, depth});
    if (m.gbuffer) m.parts.push_back({"lit depth " + depthFormat + " (depth copy)", depth});
    if (mode == LightingMode::Tiled || mode == LightingMode::ForwardPlus)
        m.parts.push_back({"tile light lists", tileListBytesPerPixel(width, height, maxStorageBlockBytes)});
    return m;
}

}  // namespace gbl
