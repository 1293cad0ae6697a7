// Allocation of the G-buffer, the HDR target, the display target and the overlays' framebuffers.
#include "gpu/render_targets.h"

#include <string>
#include <vector>

namespace gbl {

GLenum glInternalFormat(TexelFormat f) {
    switch (f) {
        case TexelFormat::RGBA16F:
            return GL_RGBA16F;
        case TexelFormat::RG16:
            return GL_RG16;
        case TexelFormat::RGBA8:
            return GL_RGBA8;
        case TexelFormat::RGB10A2:
            return GL_RGB10_A2;
        case TexelFormat::Depth32FStencil8:
            return GL_DEPTH32F_STENCIL8;
        case TexelFormat::Depth24Stencil8:
            return GL_DEPTH24_STENCIL8;
    }
    return GL_RGBA8;
}

std::optional<std::string> createRenderTargets(int width, int height, GBufferLayout layout, RenderTargets& out) {
    out = RenderTargets{};
    out.gbuffer.layout = layout;
    out.width = width;
    out.height = height;
    if (out.empty()) return std::nullopt;
    using gl::Framebuffer;
    using gl::Texture;
    GBuffer& g = out.gbuffer;
    GBufferLayoutDesc const& desc = layoutDesc(layout);
    std::vector<Texture const*> colors;
    for (GBufferAttachmentDesc const& a : desc.attachments()) {
        Texture& t = const_cast<Texture&>(g.texture(a.slot));
        t = Texture::create2D(glInternalFormat(a.format), width, height, "gbuffer." + std::string(a.name));
        if (a.slot != GBufferSlot::Depth) colors.push_back(&t);
    }
    // The colour attachments in the layout's order: geometry.frag writes them at locations 0, 1, ...
    g.fbo = Framebuffer::create(colors, &g.depth, "gbuffer");

    out.lighting = Texture::create2D(GL_RGBA16F, width, height, "lighting.hdr");
    out.litDepth = Texture::create2D(glInternalFormat(desc.depthFormat()), width, height, "lighting.depth");
    out.litFbo = Framebuffer::create({&out.lighting}, &out.litDepth, "lighting");
    if (lightingSamplesDepth(desc))
        out.volumeDepth = Texture::create2D(glInternalFormat(desc.depthFormat()), width, height, "volumes.depth");
    Texture const* volumeDepth = &out.volumeDepthStencil();
    out.volumeFbo = Framebuffer::create({&out.lighting}, volumeDepth, "lighting.volumes");
    out.diffuseLight = Texture::create2D(GL_RGBA16F, width, height, "lighting.diffuse");
    out.specularLight = Texture::create2D(GL_RGBA16F, width, height, "lighting.specular");
    out.splitFbo = Framebuffer::create({&out.diffuseLight, &out.specularLight}, nullptr, "lighting.split");
    out.splitVolumeFbo =
        Framebuffer::create({&out.diffuseLight, &out.specularLight}, volumeDepth, "lighting.split.volumes");
    out.prepassNormal = Texture::create2D(GL_RGBA16F, width, height, "prepass.normal_exp");
    out.prepassFbo = Framebuffer::create({&out.prepassNormal}, &out.litDepth, "prepass.thin_gbuffer");
    out.coverage = Texture::create2D(GL_RG32F, width, height, "coverage");
    out.coverageFbo = Framebuffer::create({&out.coverage}, volumeDepth, "coverage");
    out.display = Texture::create2D(GL_RGBA8, width, height, "display");
    out.displayFbo = Framebuffer::create({&out.display}, nullptr, "display");
    out.overlayFbo = Framebuffer::create({&out.display}, &out.litDepth, "display.overlays");
    out.overlayGBufferDepthFbo = Framebuffer::create({&out.display}, &g.depth, "display.overlays.gbuffer_depth");

    for (Framebuffer const* fb :
         {&g.fbo, &out.litFbo, &out.volumeFbo, &out.splitFbo, &out.splitVolumeFbo, &out.prepassFbo, &out.coverageFbo,
          &out.displayFbo, &out.overlayFbo, &out.overlayGBufferDepthFbo})
        if (fb->error()) return fb->error();
    return std::nullopt;
}

}  // namespace gbl
