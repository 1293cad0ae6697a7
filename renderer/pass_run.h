// What the executor hands a pass's run function: its declaration and what it declared, resolved
// (renderer_passes.cpp runs every declared pass through one of these).
#pragma once

#include "core/frame_passes.h"
#include "gpu/frame_resources.h"

#include <functional>

namespace gbl {

struct PassRun {
    PassDecl const& decl;
    FrameResources const& io;
    gl::Framebuffer const* fbo;  // the declared colour and depth-stencil (raster, blit); null for compute
};
using RunPass = std::function<void(PassRun const&)>;

}  // namespace gbl
