// The image a view pass draws into (see core/view_params.h for what a view shows).
#pragma once

#include "core/view_params.h"
#include "gl/framebuffer.h"
#include "gl/texture.h"

namespace gbl {

// An RGBA8 image a view is drawn into, sized like the frame targets.
struct ViewTarget {
    gl::Texture texture;
    gl::Framebuffer fbo;
};

}  // namespace gbl
