// What a view of a frame image shows: the final picture or a remapped debug view of an attachment.
// The viewport and every texture viewer of the editor describe their view with these values.
#pragma once

#include "core/pipeline_settings.h"

namespace gbl {

// Values match NORMALS_* in shaders/view_constants.glsl (shader_constants_test checks them).
enum class NormalDisplay { Biased = 0, Absolute = 1 };

// Viewer tools (issue 15). Values match COLORMAP_* and OVERLAY_* in shaders/view_constants.glsl
// (shader_constants_test checks them).
enum class Colormap { Grey = 0, Turbo = 1, Viridis = 2 };
// In enum order; COLORMAP_ + the upper-cased name in the shader.
inline constexpr std::array<std::string_view, 3> kColormapNames{"grey", "turbo", "viridis"};
inline constexpr unsigned kOverlayNaN = 1u;       // magenta where a shown channel is NaN
inline constexpr unsigned kOverlayInf = 2u;       // green where a shown channel is +-Inf
inline constexpr unsigned kOverlayNegative = 4u;  // cyan where a shown channel is below 0
inline constexpr unsigned kOverlayClip = 8u;      // blue below the black point, red above the white point

struct ViewParams {
    DebugView view = DebugView::Final;
    unsigned channelMask = 0xF;  // bit 0 = R, 1 = G, 2 = B, 3 = A; one bit alone shows grey
    float rangeMin = 0.0f;       // data views show (v - min) / (max - min)
    float rangeMax = 1.0f;
    NormalDisplay normalDisplay = NormalDisplay::Biased;
    Colormap colormap = Colormap::Grey;  // applied when one channel is shown
    unsigned overlays = 0;               // kOverlay* bits

    // Every member, floats compared with ==: "does the target show something else now".
    bool operator==(ViewParams const&) const = default;
};

}  // namespace gbl
