// The G-buffer layouts: one description per layout (attachments, formats, bytes, how position and
// normal are stored), read by the render targets, the shader library's defines, read-back and export.
#pragma once

#include "core/pipeline_settings.h"

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gbl {

// Texel formats the layouts use. gpu/render_targets.cpp maps them to GL internal formats.
enum class TexelFormat { RGBA16F, RG16, RGBA8, RGB10A2, Depth32FStencil8, Depth24Stencil8 };

// Bytes one texel of `f` occupies. DEPTH32F_STENCIL8 is a 64-bit texel (GL's packed type
// FLOAT_32_UNSIGNED_INT_24_8_REV: 24 bits of padding), so it counts 8, not 5.
constexpr int texelBytes(TexelFormat f) {
    switch (f) {
        case TexelFormat::RGBA16F:
        case TexelFormat::Depth32FStencil8:
            return 8;
        case TexelFormat::RG16:
        case TexelFormat::RGBA8:
        case TexelFormat::RGB10A2:
        case TexelFormat::Depth24Stencil8:
            return 4;
    }
    return 0;
}

constexpr std::string_view texelFormatName(TexelFormat f) {
    constexpr std::array<std::string_view, 6> names{"RGBA16F",         "RG16", "RGBA8", "RGB10_A2", "DEPTH32F_STENCIL8",
                                                    "DEPTH24_STENCIL8"};
    return names[std::size_t(f)];
}

// How the normal attachment holds the unit normal n (shaders/gbuffer_encoding.glsl encodes and
// decodes, core/octahedral.h is the C++ twin of the octahedral one).
enum class NormalEncoding {
    Float,       // xyz = n, w = 1
    Biased,      // xyz = n * 0.5 + 0.5 in a unorm target, w = 1
    Octahedral,  // xy = oct(n) * 0.5 + 0.5 in RG16 unorm
};

// Which texture of the G-buffer an attachment is.
// Emissive: rgb = the material's emitted radiance (linear), a = its ambient occlusion (docs/gbuffer_layouts.md).
enum class GBufferSlot { Position, Normal, AlbedoSpec, Emissive, Depth };

struct GBufferAttachmentDesc {
    GBufferSlot slot;
    std::string_view name;  // raw_<name>.exr / .png on export
    TexelFormat format;
};

struct GBufferLayoutDesc {
    std::string_view name;  // as in kGBufferLayoutNames
    bool storesPosition;    // false: rebuilt from depth and the inverse view-projection
    NormalEncoding normalEncoding;
    // Colour attachments in draw-buffer order (location 0, 1, ...), then the depth-stencil.
    std::array<GBufferAttachmentDesc, 5> attachmentArray;
    int attachmentCount;

    std::span<GBufferAttachmentDesc const> attachments() const {
        return {attachmentArray.data(), std::size_t(attachmentCount)};
    }
    std::span<GBufferAttachmentDesc const> colorAttachments() const {
        return {attachmentArray.data(), std::size_t(attachmentCount - 1)};
    }
    TexelFormat depthFormat() const { return attachmentArray[std::size_t(attachmentCount - 1)].format; }
};

// The one table of layouts, in GBufferLayout order. Layouts that rebuild position use a 24-bit
// depth; classic keeps a 32-bit float depth. Emissive + occlusion take one more attachment where
// there is room: RGBA16F in classic (room for emission above 1), RGBA8 in the teaching layouts
// naive8 and rgb10a2 (16 bytes a pixel, no byte target). packed keeps the 12 bytes, where no
// spare channel holds four more values, so it stores neither: it decodes emission 0 and occlusion 1.
inline constexpr std::array<GBufferLayoutDesc, 4> kGBufferLayouts{{
    {"classic",
     true,
     NormalEncoding::Float,
     {{{GBufferSlot::Position, "position", TexelFormat::RGBA16F},
       {GBufferSlot::Normal, "normal", TexelFormat::RGBA16F},
       {GBufferSlot::AlbedoSpec, "albedo_spec", TexelFormat::RGBA8},
       {GBufferSlot::Emissive, "emissive_ao", TexelFormat::RGBA16F},
       {GBufferSlot::Depth, "depth", TexelFormat::Depth32FStencil8}}},
     5},
    {"packed",
     false,
     NormalEncoding::Octahedral,
     {{{GBufferSlot::Normal, "normal_oct", TexelFormat::RG16},
       {GBufferSlot::AlbedoSpec, "albedo_spec", TexelFormat::RGBA8},
       {GBufferSlot::Depth, "depth", TexelFormat::Depth24Stencil8}}},
     3},
    {"naive8",
     false,
     NormalEncoding::Biased,
     {{{GBufferSlot::Normal, "normal8", TexelFormat::RGBA8},
       {GBufferSlot::AlbedoSpec, "albedo_spec", TexelFormat::RGBA8},
       {GBufferSlot::Emissive, "emissive_ao", TexelFormat::RGBA8},
       {GBufferSlot::Depth, "depth", TexelFormat::Depth24Stencil8}}},
     4},
    {"rgb10a2",
     false,
     NormalEncoding::Biased,
     {{{GBufferSlot::Normal, "normal10", TexelFormat::RGB10A2},
       {GBufferSlot::AlbedoSpec, "albedo_spec", TexelFormat::RGBA8},
       {GBufferSlot::Emissive, "emissive_ao", TexelFormat::RGBA8},
       {GBufferSlot::Depth, "depth", TexelFormat::Depth24Stencil8}}},
     4},
}};

constexpr GBufferLayoutDesc const& layoutDesc(GBufferLayout l) {
    return kGBufferLayouts[std::size_t(l)];
}

// The colour-attachment index (draw buffer) of `slot`, or -1 when the layout does not store it.
constexpr int colorAttachmentIndex(GBufferLayoutDesc const& d, GBufferSlot slot) {
    for (int i = 0; i + 1 < d.attachmentCount; ++i)
        if (d.attachmentArray[std::size_t(i)].slot == slot) return i;
    return -1;
}

// Whether the layout has an emissive_ao attachment (layouts without one decode emission 0, occlusion 1).
constexpr bool storesEmissiveAo(GBufferLayoutDesc const& d) {
    return colorAttachmentIndex(d, GBufferSlot::Emissive) >= 0;
}

// Whether the G-buffer readers (gbuffer_read.glsl) sample the depth-stencil texture to rebuild
// position. Where they do, a pass that reads the G-buffer and depth-tests against the scene must
// not have that texture attached: it draws against a copy (RenderTargets::volumeDepth).
constexpr bool lightingSamplesDepth(GBufferLayoutDesc const& d) {
    return !d.storesPosition;
}

// The #defines that select this layout's encode (geometry.frag) and decode (gbuffer_read.glsl).
inline std::vector<std::string> layoutShaderDefines(GBufferLayoutDesc const& d) {
    std::vector<std::string> out;
    if (!d.storesPosition) out.push_back("GBUFFER_POSITION_FROM_DEPTH");
    switch (d.normalEncoding) {
        case NormalEncoding::Float:
            break;
        case NormalEncoding::Biased:
            out.push_back("GBUFFER_NORMAL_BIASED");
            break;
        case NormalEncoding::Octahedral:
            out.push_back("GBUFFER_NORMAL_OCTAHEDRAL");
            break;
    }
    if (!storesEmissiveAo(d)) out.push_back("GBUFFER_NO_EMISSIVE_AO");
    return out;
}

// --- memory --------------------------------------------------------------------------------------

constexpr int layoutBytesPerPixel(GBufferLayoutDesc const& d) {
    int sum = 0;
    for (int i = 0; i < d.attachmentCount; ++i) sum += texelBytes(d.attachmentArray[std::size_t(i)].format);
    return sum;
}

// Megabytes (10^6 bytes) the layout's attachments take at width x height.
constexpr double layoutMegabytes(GBufferLayoutDesc const& d, int width, int height) {
    return double(layoutBytesPerPixel(d)) * double(width) * double(height) / 1.0e6;
}

// prepass mode (docs/deferred_lighting.md) draws none of the layout's attachments: its thin G-buffer
// is an RGBA16F normal and specular exponent with the lit target's depth (the layout's depth format),
// and its light pass adds two RGBA16F targets, diffuse and specular light.
inline int prepassThinBytesPerPixel(GBufferLayoutDesc const& d) {
    return texelBytes(TexelFormat::RGBA16F) + texelBytes(d.depthFormat());
}
inline constexpr int kPrepassLightBytesPerPixel = 2 * texelBytes(TexelFormat::RGBA16F);

// What the user is told when the layout does not store emission and occlusion (stats panel, pixel
// inspector, export's stats.json); empty when it does.
inline std::string layoutOmissionNote(GBufferLayoutDesc const& d) {
    if (storesEmissiveAo(d)) return {};
    return std::string(d.name) + ": no room for emissive and occlusion in " + std::to_string(layoutBytesPerPixel(d)) +
           " bytes; emission and AO are not shown";
}

}  // namespace gbl
