// The per-pixel memory of each mode's frame (core/frame_memory.h): the deferred modes count their
// G-buffer, the forward modes none; forward+ counts its depth pre-pass, lit image and tile lists.
#include "core/frame_memory.h"

#include <gtest/gtest.h>

using namespace gbl;

namespace {

// A storage-block limit large enough for the full list cap (kTileBinMaxLights) at 1280x720.
constexpr long long kLargeBlock = 128LL << 20;

}  // namespace

TEST(FrameMemory, DeferredModesCountTheirGBufferAndTheLitTarget) {
    GBufferLayoutDesc const& classic = layoutDesc(GBufferLayout::Classic);
    FrameMemory const quad = frameMemory(LightingMode::Quad, classic, 1280, 720, kLargeBlock);
    EXPECT_TRUE(quad.gbuffer);
    // classic 36 + lit image RGBA16F 8 + its depth-stencil DEPTH32F_STENCIL8 8 (the depth copy's).
    EXPECT_DOUBLE_EQ(quad.bytesPerPixel(), 36.0 + 8.0 + 8.0);
    ASSERT_FALSE(quad.parts.empty());
    EXPECT_EQ(quad.parts.front(), (MemoryPart{"G-buffer (classic)", 36.0}));
    // packed: 12 + 8 + DEPTH24_STENCIL8 4.
    EXPECT_DOUBLE_EQ(
        frameMemory(LightingMode::Volumes, layoutDesc(GBufferLayout::Packed), 1280, 720, kLargeBlock).bytesPerPixel(),
        12.0 + 8.0 + 4.0);
}

TEST(FrameMemory, ForwardModesWriteNoGBuffer) {
    GBufferLayoutDesc const& packed = layoutDesc(GBufferLayout::Packed);
    FrameMemory const forward = frameMemory(LightingMode::Forward, packed, 1280, 720, kLargeBlock);
    EXPECT_FALSE(forward.gbuffer);
    EXPECT_EQ(forward.parts, (std::vector<MemoryPart>{{"lit image RGBA16F", 8.0}, {"depth DEPTH24_STENCIL8", 4.0}}));
    FrameMemory const plus = frameMemory(LightingMode::ForwardPlus, packed, 1280, 720, kLargeBlock);
    EXPECT_FALSE(plus.gbuffer);
    // 80 x 45 tiles of 256 pixels, each a count (4 B), a depth range (8 B) and 1024 indices (4 B each).
    double const lists = (4.0 + 8.0 + 4.0 * 1024.0) / 256.0;
    EXPECT_DOUBLE_EQ(tileListBytesPerPixel(1280, 720, kLargeBlock), lists);
    EXPECT_EQ(plus.parts,
              (std::vector<MemoryPart>{
                  {"depth pre-pass DEPTH24_STENCIL8", 4.0}, {"lit image RGBA16F", 8.0}, {"tile light lists", lists}}));
    EXPECT_DOUBLE_EQ(plus.bytesPerPixel(), 4.0 + 8.0 + lists);
    // tiled: the G-buffer and the same lists.
    FrameMemory const tiled = frameMemory(LightingMode::Tiled, packed, 1280, 720, kLargeBlock);
    EXPECT_DOUBLE_EQ(tiled.bytesPerPixel(), 12.0 + 8.0 + 4.0 + lists);
}

TEST(FrameMemory, ASmallStorageBlockShortensTheLists) {
    // 3600 tiles and 1 MiB: 72 indices a tile (tileBinCap), so the lists take less.
    double const small = tileListBytesPerPixel(1280, 720, 1LL << 20);
    EXPECT_DOUBLE_EQ(small, (4.0 + 8.0 + 4.0 * 72.0) / 256.0);
    EXPECT_EQ(tileListBytesPerPixel(0, 0, kLargeBlock), 0.0);
}

TEST(FrameMemory, PrepassCountsItsThinGBufferAndLightTargets) {
    // docs/deferred_lighting.md: RGBA16F normal and exponent, the lit depth, two RGBA16F light
    // targets and the lit image; none of the layout's attachments and no depth copy.
    GBufferLayoutDesc const& classic = layoutDesc(GBufferLayout::Classic);
    FrameMemory const prepass = frameMemory(LightingMode::Prepass, classic, 1280, 720, kLargeBlock);
    EXPECT_FALSE(prepass.gbuffer);
    EXPECT_EQ(prepass.parts, (std::vector<MemoryPart>{{"thin G-buffer RGBA16F (normal, exponent)", 8.0},
                                                      {"thin depth DEPTH32F_STENCIL8", 8.0},
                                                      {"light targets 2 x RGBA16F", 16.0},
                                                      {"lit image RGBA16F", 8.0}}));
    EXPECT_DOUBLE_EQ(prepass.bytesPerPixel(),
                     double(prepassThinBytesPerPixel(classic) + kPrepassLightBytesPerPixel) + 8.0);
}
