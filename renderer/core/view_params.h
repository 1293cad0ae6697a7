// What a view of a frame image shows: the final picture or a remapped debug view of an attachment.
// The viewport and every texture viewer of the editor describe their view with these values.
#pragma once

#include "core/pipeline_settings.h"

namespace gbl {

// Values match NORMALS_* in shaders/view_constants.glsl (shader_constants_test checks them).
enum class NormalDisplay { Biased = 0, Absolute = 1 };

struct ViewParams {
    DebugView view = DebugView::Final;
    unsigned channelMask = 0xF;  // bit 0 = R, 1 = G, 2 = B, 3 = A; one bit alone shows grey
    float rangeMin = 0.0f;       // data views show (v - min) / (max - min)
    float rangeMax = 1.0f;
    NormalDisplay normalDisplay = NormalDisplay::Biased;
    float heatMax = 16.0f;       // count at the top of the heat ramp

    // Every member, floats compared with ==: "does the target show something else now".
    bool operator==(ViewParams const&) const = default;
};

}  // namespace gbl
