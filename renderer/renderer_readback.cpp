// Reading the frame's images back: attachments as floats, one pixel for the inspector, views.
#include "renderer_impl.h"

#include "passes/gbuffer_decode.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace gbl {

unsigned Renderer::texture(Attachment a) const {
    RenderTargets const& t = impl_->targets;
    switch (a) {
        case Attachment::Position:
            return t.gbuffer.position.id();
        case Attachment::Normal:
            return t.gbuffer.normal.id();
        case Attachment::AlbedoSpec:
            return t.gbuffer.albedoSpec.id();
        case Attachment::Emissive:
            return t.gbuffer.emissive.id();
        case Attachment::DiffuseLight:
            return t.diffuseLight.id();
        case Attachment::SpecularLight:
            return t.specularLight.id();
        case Attachment::Depth:
        case Attachment::Stencil:  // one texture holds both; sampling stencil needs its texture mode
            return t.gbuffer.depth.id();
        case Attachment::Lighting:
            return t.lighting.id();
        case Attachment::Coverage:
            return t.coverage.id();
        case Attachment::Final:
            return t.display.id();
    }
    return 0;
}

namespace {
// A width x height RGBA image of one value (what a layout decodes for a quantity it does not store).
FloatImage constantImage(int width, int height, glm::vec4 v) {
    FloatImage img{width, height, 4, {}};
    img.pixels.reserve(std::size_t(width) * std::size_t(height) * 4);
    for (int i = 0; i < width * height; ++i) img.pixels.insert(img.pixels.end(), {v.x, v.y, v.z, v.w});
    return img;
}

// Reads a whole framebuffer attachment as floats, flipped so rows run top to bottom: one channel
// reads depth, two read RG, four RGBA.
FloatImage readFramebuffer(GLuint fbo, GLenum attachment, int width, int height, int channels) {
    FloatImage img;
    img.width = width;
    img.height = height;
    img.channels = channels;
    img.pixels.resize(std::size_t(width) * height * channels);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    if (attachment != GL_NONE) glReadBuffer(attachment);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    GLenum const format = channels == 1 ? GL_DEPTH_COMPONENT : channels == 2 ? GL_RG : GL_RGBA;
    glReadPixels(0, 0, width, height, format, GL_FLOAT, img.pixels.data());
    if (attachment != GL_NONE) glReadBuffer(GL_COLOR_ATTACHMENT0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    // GL rows run bottom to top; images and mouse coordinates run top to bottom.
    std::size_t const row = std::size_t(width) * channels;
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(img.pixels.begin() + std::ptrdiff_t(y * row),
                         img.pixels.begin() + std::ptrdiff_t((y + 1) * row),
                         img.pixels.begin() + std::ptrdiff_t((height - 1 - y) * row));
    return img;
}

// Reads the stencil bits of a framebuffer's depth-stencil attachment as one float channel holding
// the integer values, flipped like readFramebuffer.
FloatImage readStencil(GLuint fbo, int width, int height) {
    std::vector<std::uint8_t> bytes(std::size_t(width) * height);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, bytes.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    FloatImage img;
    img.width = width;
    img.height = height;
    img.channels = 1;
    img.pixels.resize(bytes.size());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            img.pixels[std::size_t(y) * width + x] = float(bytes[std::size_t(height - 1 - y) * width + x]);
    return img;
}
}  // namespace

namespace {
// Runs the decode pass over width x height G-buffer pixels from `offset` (GL's bottom-left origin).
DecodedGBuffer decodeGBuffer(RendererImpl& r, glm::ivec2 offset, int width, int height, glm::mat4 const& invViewProj) {
    DecodedGBuffer d = createDecodedGBuffer(width, height);
    gbufferDecodePass({r.targets.gbuffer, r.shaders.get(ProgramId::GBufferDecode), r.triangle, d},
                      {invViewProj, offset});
    return d;
}

int texelChannels(TexelFormat f) {
    return f == TexelFormat::RG16 ? 2 : f == TexelFormat::Depth24Stencil8 || f == TexelFormat::Depth32FStencil8 ? 1 : 4;
}
}  // namespace

GBufferLayout Renderer::layout() const {
    return impl_->targets.gbuffer.layout;
}

FloatImage Renderer::readRawAttachment(int index) const {
    RenderTargets const& t = impl_->targets;
    GBufferLayoutDesc const& desc = layoutDesc(t.gbuffer.layout);
    if (t.empty() || index < 0 || index >= desc.attachmentCount) return {};
    TexelFormat const f = desc.attachments()[std::size_t(index)].format;
    bool const depth = index == desc.attachmentCount - 1;
    return readFramebuffer(t.gbuffer.fbo.id(), depth ? GL_NONE : GLenum(GL_COLOR_ATTACHMENT0 + index), t.width,
                           t.height, texelChannels(f));
}

FloatImage Renderer::readAttachment(Attachment a) const {
    RenderTargets const& t = impl_->targets;
    if (t.empty()) return {};
    int const albedoIndex = colorAttachmentIndex(layoutDesc(t.gbuffer.layout), GBufferSlot::AlbedoSpec);
    int const emissiveIndex = colorAttachmentIndex(layoutDesc(t.gbuffer.layout), GBufferSlot::Emissive);
    switch (a) {
        case Attachment::Position:
        case Attachment::Normal: {
            DecodedGBuffer const d = decodeGBuffer(*impl_, {0, 0}, t.width, t.height, impl_->frameInverseViewProj);
            return readFramebuffer(d.fbo.id(), a == Attachment::Position ? GL_COLOR_ATTACHMENT0 : GL_COLOR_ATTACHMENT1,
                                   t.width, t.height, 4);
        }
        case Attachment::AlbedoSpec:
            return readFramebuffer(t.gbuffer.fbo.id(), GLenum(GL_COLOR_ATTACHMENT0 + albedoIndex), t.width, t.height,
                                   4);
        case Attachment::Emissive:
            if (emissiveIndex < 0) return constantImage(t.width, t.height, kNoEmissiveAo);
            return readFramebuffer(t.gbuffer.fbo.id(), GLenum(GL_COLOR_ATTACHMENT0 + emissiveIndex), t.width, t.height,
                                   4);
        case Attachment::Depth:
            return readFramebuffer(t.gbuffer.fbo.id(), GL_NONE, t.width, t.height, 1);
        case Attachment::Stencil:
            return readStencil(t.gbuffer.fbo.id(), t.width, t.height);
        case Attachment::Lighting:
            return readFramebuffer(t.litFbo.id(), GL_COLOR_ATTACHMENT0, t.width, t.height, 4);
        case Attachment::DiffuseLight:
        case Attachment::SpecularLight:
            return readFramebuffer(t.splitFbo.id(),
                                   a == Attachment::DiffuseLight ? GL_COLOR_ATTACHMENT0 : GL_COLOR_ATTACHMENT1, t.width,
                                   t.height, 4);
        case Attachment::Coverage:
            return readFramebuffer(t.coverageFbo.id(), GL_COLOR_ATTACHMENT0, t.width, t.height, 2);
        case Attachment::Final:
            return readFramebuffer(t.displayFbo.id(), GL_COLOR_ATTACHMENT0, t.width, t.height, 4);
    }
    return {};
}

FloatImage Renderer::readViewTarget(ViewTarget const& target) const {
    if (!target.texture) return {};
    return readFramebuffer(target.fbo.id(), GL_COLOR_ATTACHMENT0, target.texture.width(), target.texture.height(), 4);
}

PixelSample Renderer::samplePixel(int x, int y, Camera const& camera) const {
    RenderTargets const& t = impl_->targets;
    PixelSample s;
    if (t.empty() || x < 0 || y < 0 || x >= t.width || y >= t.height) return s;
    int const glY = t.height - 1 - y;
    auto readColor = [&](GLuint fbo, GLenum attachment, glm::vec4& out) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
        glReadBuffer(attachment);
        glReadPixels(x, glY, 1, 1, GL_RGBA, GL_FLOAT, &out[0]);
        glReadBuffer(GL_COLOR_ATTACHMENT0);
    };
    GBufferLayoutDesc const& desc = layoutDesc(t.gbuffer.layout);
    float const aspect = float(t.width) / float(t.height);
    glm::mat4 const invViewProj = glm::inverse(camera.projection(aspect) * camera.view());
    // Position and normal as the lighting decoded them, through a one-pixel decode pass.
    DecodedGBuffer const d = decodeGBuffer(*impl_, {x, glY}, 1, 1, invViewProj);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, d.fbo.id());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, &s.position[0]);
    glReadBuffer(GL_COLOR_ATTACHMENT1);
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, &s.normal[0]);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    readColor(t.gbuffer.fbo.id(), GLenum(GL_COLOR_ATTACHMENT0 + colorAttachmentIndex(desc, GBufferSlot::Normal)),
              s.rawNormal);
    readColor(t.gbuffer.fbo.id(), GLenum(GL_COLOR_ATTACHMENT0 + colorAttachmentIndex(desc, GBufferSlot::AlbedoSpec)),
              s.albedoSpec);
    if (int const e = colorAttachmentIndex(desc, GBufferSlot::Emissive); e >= 0)
        readColor(t.gbuffer.fbo.id(), GLenum(GL_COLOR_ATTACHMENT0 + e), s.emissiveAo);
    else
        s.emissiveAo = kNoEmissiveAo;
    readColor(t.litFbo.id(), GL_COLOR_ATTACHMENT0, s.lighting);
    if (impl_->coverageView) {
        glm::vec4 c{0.0f};
        readColor(t.coverageFbo.id(), GL_COLOR_ATTACHMENT0, c);
        s.coverage = glm::vec2(c);
        s.coverageView = impl_->coverageView;
        s.coverageMode = impl_->coverageMode;
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, t.gbuffer.fbo.id());
    glReadPixels(x, glY, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &s.depth);
    std::uint8_t stencil = 0;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(x, glY, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &stencil);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    s.stencil = stencil;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    s.covered = s.position.w > 0.0f;
    // World position rebuilt from depth: unproject the pixel centre through the inverse view-projection.
    glm::vec4 const ndc((float(x) + 0.5f) / float(t.width) * 2.0f - 1.0f,
                        (float(glY) + 0.5f) / float(t.height) * 2.0f - 1.0f, s.depth * 2.0f - 1.0f, 1.0f);
    glm::vec4 const world = invViewProj * ndc;
    s.reconstructedPosition = glm::vec3(world) / world.w;
    return s;
}

}  // namespace gbl
