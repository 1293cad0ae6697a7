// The multisampled G-buffer and the complex pixels' mask (docs/msaa.md).
#include "gpu/render_targets.h"

#include <string>
#include <vector>

namespace gbl {

std::optional<std::string> createMsaaTargets(int samples, RenderTargets& out) {
    out.msaa = MsaaTargets{};
    if (out.empty()) return std::nullopt;
    using gl::Framebuffer;
    using gl::Texture;
    MsaaTargets m;
    m.samples = samples;
    m.gbuffer.layout = out.gbuffer.layout;
    std::vector<Texture const*> colors;
    for (GBufferAttachmentDesc const& a : layoutDesc(out.gbuffer.layout).attachments()) {
        Texture& t = const_cast<Texture&>(m.gbuffer.texture(a.slot));
        t = Texture::create2DMultisample(glInternalFormat(a.format), out.width, out.height, samples,
                                         "msaa." + std::string(a.name));
        if (a.slot != GBufferSlot::Depth) colors.push_back(&t);
    }
    m.gbuffer.fbo = Framebuffer::create(colors, &m.gbuffer.depth, "msaa.gbuffer");
    m.complexMask = Texture::create2D(GL_R8, out.width, out.height, "msaa.complex_mask");
    m.complexFbo = Framebuffer::create({&m.complexMask}, &out.litDepth, "msaa.complex");
    for (Framebuffer const* fb : {&m.gbuffer.fbo, &m.complexFbo})
        if (fb->error()) return fb->error();
    out.msaa = std::move(m);
    return std::nullopt;
}

}  // namespace gbl
