// The volume depth copy: the G-buffer's depth-stencil blitted into the depth-stencil the volume
// passes test against, so they never sample a texture attached to the framebuffer they draw into.
#pragma once

#include "gl/framebuffer.h"

namespace gbl {

struct VolumeDepthInput {
    gl::Framebuffer const& source;  // read: its depth-stencil (the G-buffer's)
    gl::Framebuffer const& target;  // written: its depth-stencil (volumeFbo's volumeDepth)
};
struct VolumeDepthConfig {
    int width = 0;
    int height = 0;
    bool stencil = true;  // false: the depth alone (msaa volumes keep the complex bit in the target's stencil)
};
struct VolumeDepthOutput {
    gl::Framebuffer const& target;
};

// Depth and stencil in one blit, or the depth alone (the two textures share the layout's depth
// format, as a depth blit requires; from a multisampled source the blit takes one sample). Blits bypass the fragment
// pipeline, so no depth, stencil or blend state matters.
VolumeDepthOutput volumeDepthPass(VolumeDepthInput const& in, VolumeDepthConfig const& config);

}  // namespace gbl
