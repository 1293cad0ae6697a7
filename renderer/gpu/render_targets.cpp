// Allocation of the G-buffer, the HDR target and the display target.
#include "gpu/render_targets.h"

namespace gbl {

std::optional<std::string> createRenderTargets(int width, int height, RenderTargets& out) {
    out = RenderTargets{};
    out.width = width;
    out.height = height;
    if (out.empty()) return std::nullopt;
    using gl::Framebuffer;
    using gl::Texture;
    GBuffer& g = out.gbuffer;
    g.position = Texture::create2D(GL_RGBA16F, width, height, "gbuffer.position");
    g.normal = Texture::create2D(GL_RGBA16F, width, height, "gbuffer.normal");
    g.albedoSpec = Texture::create2D(GL_RGBA8, width, height, "gbuffer.albedo_spec");
    g.depth = Texture::create2D(GL_DEPTH32F_STENCIL8, width, height, "gbuffer.depth");
    g.fbo = Framebuffer::create({&g.position, &g.normal, &g.albedoSpec}, &g.depth, "gbuffer");

    out.lighting = Texture::create2D(GL_RGBA16F, width, height, "lighting.hdr");
    out.litDepth = Texture::create2D(GL_DEPTH32F_STENCIL8, width, height, "lighting.depth");
    out.litFbo = Framebuffer::create({&out.lighting}, &out.litDepth, "lighting");
    out.volumeFbo = Framebuffer::create({&out.lighting}, &g.depth, "lighting.volumes");
    out.coverage = Texture::create2D(GL_RG32F, width, height, "coverage");
    out.coverageFbo = Framebuffer::create({&out.coverage}, &g.depth, "coverage");
    out.display = Texture::create2D(GL_RGBA8, width, height, "display");
    out.displayFbo = Framebuffer::create({&out.display}, nullptr, "display");

    for (Framebuffer const* fb : {&g.fbo, &out.litFbo, &out.volumeFbo, &out.coverageFbo, &out.displayFbo})
        if (fb->error()) return fb->error();
    return std::nullopt;
}

}  // namespace gbl
