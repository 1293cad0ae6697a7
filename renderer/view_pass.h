// Display of a frame image: the final tonemapped picture or a remapped debug view of an
// attachment. The viewport and every texture viewer of the editor go through this pass.
#pragma once

#include "gl/framebuffer.h"
#include "gl/texture.h"
#include "pipeline_settings.h"

namespace gbl {

// Values match NORMALS_* in shaders/view.frag.
enum class NormalDisplay { Biased = 0, Absolute = 1 };

struct ViewParams {
    DebugView view = DebugView::Final;
    unsigned channelMask = 0xF;  // bit 0 = R, 1 = G, 2 = B, 3 = A; one bit alone shows grey
    float rangeMin = 0.0f;       // data views show (v - min) / (max - min)
    float rangeMax = 1.0f;
    NormalDisplay normalDisplay = NormalDisplay::Biased;
    float heatMax = 16.0f;       // count at the top of the heat ramp
};

// An RGBA8 image a view is drawn into, sized like the frame targets.
struct ViewTarget {
    gl::Texture texture;
    gl::Framebuffer fbo;
};

}  // namespace gbl
