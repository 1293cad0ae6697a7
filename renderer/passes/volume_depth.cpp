// The volume depth copy.
#include "passes/volume_depth.h"

namespace gbl {

VolumeDepthOutput volumeDepthPass(VolumeDepthInput const& in, VolumeDepthConfig const& config) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, in.source.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, in.target.id());
    glBlitFramebuffer(0, 0, config.width, config.height, 0, 0, config.width, config.height,
                      GL_DEPTH_BUFFER_BIT | (config.stencil ? GL_STENCIL_BUFFER_BIT : 0), GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return {in.target};
}

}  // namespace gbl
