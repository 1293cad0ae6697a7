// The multisampled G-buffer and the complex pixels' mask (docs/msaa.md).
#include "gpu/render_targets.h"

#include <string>
#include <vector>

namespace gbl {

namespace {

// Whether the driver gave `t` its storage: a multisample texture it could not allocate
// (GL_OUT_OF_MEMORY) keeps a level 0 of width 0.
bool allocated(gl::Texture const& t) {
    GLint width = 0;
    if constexpr (!gl::kWebGL2) {  // no multisample textures there, and no level queries
        glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, t.id());
        glGetTexLevelParameteriv(GL_TEXTURE_2D_MULTISAMPLE, 0, GL_TEXTURE_WIDTH, &width);
        glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
    }
    return width > 0;
}

}  // namespace

std::optional<std::string> createMsaaTargets(int samples, RenderTargets& out) {
    out.msaa = MsaaTargets{};
    if (out.empty()) return std::nullopt;
    using gl::Framebuffer;
    using gl::Texture;
    MsaaTargets m;
    m.samples = samples;
    m.gbuffer.layout = out.gbuffer.layout;
    GBufferLayoutDesc const& desc = layoutDesc(out.gbuffer.layout);
    auto const multisampled = [&](Texture& t, GLenum format, std::string const& label) -> std::optional<std::string> {
        t = Texture::create2DMultisample(format, out.width, out.height, samples, label);
        if (allocated(t)) return std::nullopt;
        return "the driver could not allocate " + label + " (GL_OUT_OF_MEMORY)";
    };
    std::vector<Texture const*> colors;
    for (GBufferAttachmentDesc const& a : desc.attachments()) {
        Texture& t = const_cast<Texture&>(m.gbuffer.texture(a.slot));
        if (auto err = multisampled(t, glInternalFormat(a.format), "msaa." + std::string(a.name))) return err;
        if (a.slot != GBufferSlot::Depth) colors.push_back(&t);
    }
    m.gbuffer.fbo = Framebuffer::create(colors, &m.gbuffer.depth, "msaa.gbuffer");
    if constexpr (!gl::kWebGL2) {  // the bound draw framebuffer's sample places (GL 3.2)
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, m.gbuffer.fbo.id());
        for (int k = 0; k < samples; ++k) {
            GLfloat at[2] = {0.5f, 0.5f};
            glGetMultisamplefv(GL_SAMPLE_POSITION, GLuint(k), at);
            m.samplePositions.emplace_back(at[0], at[1]);
        }
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    }
    m.complexMask = Texture::create2D(GL_R8, out.width, out.height, "msaa.complex_mask");
    m.complexFbo = Framebuffer::create({&m.complexMask}, &out.litDepth, "msaa.complex");
    for (Framebuffer const* fb : {&m.gbuffer.fbo, &m.complexFbo})
        if (fb->error()) return fb->error();
    out.msaa = std::move(m);
    return std::nullopt;
}

}  // namespace gbl
