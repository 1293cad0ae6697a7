// Reading the frame's images back: attachments as floats, one pixel for the inspector, views.
#include "readback_io.h"

#include "core/depth.h"

#include "gl/shader_bindings.h"
#include "gpu/draw_state_gl.h"
#include "passes/gbuffer_decode.h"
#include "passes/shading_inputs.h"

#include <algorithm>
#include <cmath>
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
        case Attachment::ComplexPixels:
            return t.msaa.complexMask.id();
        case Attachment::PrepassNormal:
            return t.prepassNormal.id();
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

}  // namespace

#ifdef __EMSCRIPTEN__
// WebGL2 (OpenGL ES 3.0) reads a colour attachment back only as RGBA in the type its format
// implies: floats from float formats, bytes from 8-bit ones, packed words from RGB10_A2, integers
// from integer ones; never depth or stencil. Reads the bound read buffer so and widens to floats.
std::vector<float> readRgbaAsFloats(GLenum attachment, int x, int y, int width, int height) {
    GLint type = GL_FLOAT, redBits = 0;
    glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE,
                                          &type);
    glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE,
                                          &redBits);
    std::size_t const texels = std::size_t(width) * std::size_t(height);
    std::vector<float> out(texels * 4);
    if (type == GL_FLOAT) {
        glReadPixels(x, y, width, height, GL_RGBA, GL_FLOAT, out.data());
    } else if (type == GL_INT || type == GL_UNSIGNED_INT) {
        std::vector<std::uint32_t> words(texels * 4);
        glReadPixels(x, y, width, height, GL_RGBA_INTEGER, GLenum(type), words.data());
        for (std::size_t i = 0; i < words.size(); ++i)
            out[i] = type == GL_INT ? float(std::int32_t(words[i])) : float(words[i]);
    } else if (redBits == 10) {
        std::vector<std::uint32_t> words(texels);
        glReadPixels(x, y, width, height, GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV, words.data());
        for (std::size_t p = 0; p < texels; ++p) {
            std::uint32_t const w = words[p];
            out[p * 4 + 0] = float(w & 1023u) / 1023.0f;
            out[p * 4 + 1] = float((w >> 10) & 1023u) / 1023.0f;
            out[p * 4 + 2] = float((w >> 20) & 1023u) / 1023.0f;
            out[p * 4 + 3] = float(w >> 30) / 3.0f;
        }
    } else {
        std::vector<std::uint8_t> bytes(texels * 4);
        glReadPixels(x, y, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
        for (std::size_t i = 0; i < bytes.size(); ++i) out[i] = float(bytes[i]) / 255.0f;
    }
    return out;
}
#endif

// Reads a whole framebuffer attachment as floats, flipped so rows run top to bottom: one channel
// reads depth (in the browser: the red channel of a colour attachment, see readDepth), two read
// RG, four RGBA.
FloatImage readFramebuffer(GLuint fbo, GLenum attachment, int width, int height, int channels) {
    FloatImage img;
    img.width = width;
    img.height = height;
    img.channels = channels;
    img.pixels.resize(std::size_t(width) * height * channels);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    if (attachment != GL_NONE) glReadBuffer(attachment);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
#ifdef __EMSCRIPTEN__
    std::vector<float> const rgba = readRgbaAsFloats(attachment, 0, 0, width, height);
    for (std::size_t p = 0; p < std::size_t(width) * std::size_t(height); ++p)
        for (int c = 0; c < channels; ++c)
            img.pixels[p * std::size_t(channels) + std::size_t(c)] = rgba[p * 4 + std::size_t(c)];
#else
    GLenum const format = channels == 1 ? GL_DEPTH_COMPONENT : channels == 2 ? GL_RG : GL_RGBA;
    glReadPixels(0, 0, width, height, format, GL_FLOAT, img.pixels.data());
#endif
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

namespace {
#ifndef __EMSCRIPTEN__
// Reads the stencil bits of a framebuffer's depth-stencil attachment as one float channel holding
// the integer values, flipped like readFramebuffer (the browser's way is readStencilImage's).
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
#endif
}  // namespace

namespace {
// Runs the decode pass over width x height G-buffer pixels from `offset` (GL's bottom-left origin).
DecodedGBuffer decodeGBuffer(ReadbackContext const& r, glm::ivec2 offset, int width, int height,
                             glm::mat4 const& invViewProj) {
    DecodedGBuffer d = createDecodedGBuffer(width, height);
    gbufferDecodePass({gbufferTextures(r.targets.gbuffer), r.shaders.get(ProgramId::GBufferDecode), r.triangle, d},
                      {invViewProj, offset, std::span(&kDecodeState, 1)});
    return d;
}

#ifdef __EMSCRIPTEN__
// WebGL2 reads neither depth nor stencil. Depth: the depth texture is drawn into an RGBA32F target
// (shaders/texel_copy.frag) and its red channel read. Stencil: an RGBA8 target sharing the
// G-buffer's depth-stencil sums one pass per bit plane: where the stencil test passes for bit b
// (mask 1 << b), the pass adds 2^b / 255 (additive blending; sums of distinct powers of two up to
// 255 are exact in 8 bits), so the red channel times 255 is the stencil value. Only `region` (GL
// coordinates: x, y from the bottom, width, height) is drawn and read: one pixel for the inspector.
// `depth`: the depth texture drawn (the G-buffer's when null; prepass's thin one is the lit depth).
std::vector<float> readDepthOrStencil(ReadbackContext const& r, bool stencil, glm::ivec4 region,
                                      gl::Texture const* depth = nullptr) {
    RenderTargets const& t = r.targets;
    auto& rb = r.readback;  // RendererImpl::ReadbackTargets, a private type
    if (!rb.depthFbo) {
        rb.depthCopy = gl::Texture::create2D(GL_RGBA32F, t.width, t.height, "readback.depth");
        rb.depthFbo = gl::Framebuffer::create({&rb.depthCopy}, nullptr, "readback.depth");
        rb.stencilSum = gl::Texture::create2D(GL_RGBA8, t.width, t.height, "readback.stencil");
        rb.stencilFbo = gl::Framebuffer::create({&rb.stencilSum}, &t.gbuffer.depth, "readback.stencil");
    }
    gl::Framebuffer const& fbo = stencil ? rb.stencilFbo : rb.depthFbo;
    PassDecl const decl = readbackPass(stencil);  // its draw groups (core/frame_passes.h)
    // Only `region` is drawn: the viewport is the region (the shader fetches at gl_FragCoord, which
    // counts from the framebuffer's corner whatever the viewport).
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    gl::Program const& p = r.shaders.get(ProgramId::TexelCopy);
    p.use();
    if (stencil) {
        // The depth-stencil texture is attached here: left bound for sampling, WebGL calls the
        // draws a feedback loop (GL_INVALID_OPERATION) even though the constant mode reads nothing.
        bindTextureUnit(slot::BIND_READBACK_SOURCE, GL_TEXTURE_2D, 0);
        clearFramebuffer(fbo.id(), GL_COLOR_BUFFER_BIT);
        glViewport(region.x, region.y, region.z, region.w);
        p.set("uWriteConstant", 1);
        for (std::size_t bit = 0; bit < decl.states.size(); ++bit) {
            applyGroup(decl.states, bit);  // passes where bit `bit` is set, adds its constant
            p.set("uConstant", glm::vec4(float(decl.states[bit].stencilRef) / 255.0f));
            r.triangle.draw();
        }
        p.set("uWriteConstant", 0);
    } else {
        glViewport(region.x, region.y, region.z, region.w);
        applyGroup(decl.states, 0);
        bindTextureUnit(slot::BIND_READBACK_SOURCE, GL_TEXTURE_2D, depth ? depth->id() : t.gbuffer.depth.id());
        r.triangle.draw();
    }
    glViewport(0, 0, t.width, t.height);  // the frame's passes draw full size
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo.id());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    std::vector<float> const rgba = readRgbaAsFloats(GL_COLOR_ATTACHMENT0, region.x, region.y, region.z, region.w);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    std::vector<float> red(std::size_t(region.z) * std::size_t(region.w));
    for (std::size_t i = 0; i < red.size(); ++i) red[i] = stencil ? std::round(rgba[i * 4] * 255.0f) : rgba[i * 4];
    return red;
}

// The whole frame's depth or stencil, rows top to bottom.
FloatImage readDepthOrStencilImage(ReadbackContext const& r, bool stencil, gl::Texture const* depth = nullptr) {
    RenderTargets const& t = r.targets;
    std::vector<float> const bottomUp = readDepthOrStencil(r, stencil, {0, 0, t.width, t.height}, depth);
    FloatImage img{t.width, t.height, 1, std::vector<float>(bottomUp.size())};
    std::size_t const row = std::size_t(t.width);
    for (int y = 0; y < t.height; ++y)
        std::copy_n(bottomUp.begin() + std::ptrdiff_t(std::size_t(t.height - 1 - y) * row), row,
                    img.pixels.begin() + std::ptrdiff_t(std::size_t(y) * row));
    return img;
}
#endif

// The G-buffer's depth, and its stencil values, as one float channel each, rows top to bottom.
FloatImage readDepth(ReadbackContext const& r) {
#ifdef __EMSCRIPTEN__
    return readDepthOrStencilImage(r, false);
#else
    RenderTargets const& t = r.targets;
    return readFramebuffer(t.gbuffer.fbo.id(), GL_NONE, t.width, t.height, 1);
#endif
}

}  // namespace

FloatImage readDepthImage(ReadbackContext const& r, GLuint fbo, gl::Texture const& depth) {
#ifdef __EMSCRIPTEN__
    (void)fbo;
    return readDepthOrStencilImage(r, false, &depth);
#else
    (void)depth;
    return readFramebuffer(fbo, GL_NONE, r.targets.width, r.targets.height, 1);
#endif
}

float readDepthTexel(ReadbackContext const& r, GLuint fbo, gl::Texture const& depth, int x, int glY) {
#ifdef __EMSCRIPTEN__
    (void)fbo;
    return readDepthOrStencil(r, false, {x, glY, 1, 1}, &depth)[0];
#else
    (void)r;
    (void)depth;
    float d = 1.0f;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glReadPixels(x, glY, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &d);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return d;
#endif
}

namespace {
FloatImage readStencilImage(ReadbackContext const& r) {
#ifdef __EMSCRIPTEN__
    return readDepthOrStencilImage(r, true);
#else
    RenderTargets const& t = r.targets;
    return readStencil(t.gbuffer.fbo.id(), t.width, t.height);
#endif
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
    if (depth) return readDepth(impl_->readbackContext());
    return readFramebuffer(t.gbuffer.fbo.id(), depth ? GL_NONE : GLenum(GL_COLOR_ATTACHMENT0 + index), t.width,
                           t.height, texelChannels(f));
}

FloatImage Renderer::readAttachment(Attachment a) const {
    RenderTargets const& t = impl_->targets;
    if (t.empty()) return {};
    if (impl_->thinGBuffer && thinGBufferReads(a)) return impl_->readThinAttachment(a);
    int const albedoIndex = colorAttachmentIndex(layoutDesc(t.gbuffer.layout), GBufferSlot::AlbedoSpec);
    int const emissiveIndex = colorAttachmentIndex(layoutDesc(t.gbuffer.layout), GBufferSlot::Emissive);
    switch (a) {
        case Attachment::Position:
        case Attachment::Normal: {
            DecodedGBuffer const d =
                decodeGBuffer(impl_->readbackContext(), {0, 0}, t.width, t.height, impl_->frameInverseViewProj);
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
            return readDepth(impl_->readbackContext());
        case Attachment::Stencil:
            return readStencilImage(impl_->readbackContext());
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
        case Attachment::ComplexPixels:
            if (!t.msaa.complexFbo)
                return {t.width, t.height, 1, std::vector<float>(std::size_t(t.width) * std::size_t(t.height), 0.0f)};
            {  // one channel here means depth (readFramebuffer): read red and green, keep red
                FloatImage const rg =
                    readFramebuffer(t.msaa.complexFbo.id(), GL_COLOR_ATTACHMENT0, t.width, t.height, 2);
                FloatImage mask{t.width, t.height, 1, std::vector<float>(rg.pixels.size() / 2)};
                for (std::size_t i = 0; i < mask.pixels.size(); ++i) mask.pixels[i] = rg.pixels[i * 2];
                return mask;
            }
        case Attachment::PrepassNormal:
            return readFramebuffer(t.prepassFbo.id(), GL_COLOR_ATTACHMENT0, t.width, t.height, 4);
    }
    return {};
}

FloatImage Renderer::readMsaaSample(GBufferSlot slot, int sample) {
    return readMsaaSample(slot, sample, {0, 0, width(), height()});
}

// The copy pass draws only the rectangle (its viewport), so a pixel or a band of rows costs that
// much; the copy texture keeps the targets' size and is dropped with them.
FloatImage Renderer::readMsaaSample(GBufferSlot slot, int sample, glm::ivec4 rect) {
    RendererImpl& r = *impl_;
    RenderTargets const& t = r.targets;
    if (!t.msaa.gbuffer.fbo || sample < 0 || sample >= t.msaa.samples) return {};
    int const x0 = std::clamp(rect.x, 0, t.width), y0 = std::clamp(rect.y, 0, t.height);
    int const w = std::clamp(rect.z, 0, t.width - x0), h = std::clamp(rect.w, 0, t.height - y0);
    gl::Texture const& source = t.msaa.gbuffer.texture(slot);
    if (!source || w <= 0 || h <= 0) return {};
    auto& rb = r.readback;
    if (!rb.sampleFbo) {
        rb.sampleCopy = gl::Texture::create2D(GL_RGBA32F, t.width, t.height, "readback.msaa_sample");
        rb.sampleFbo = gl::Framebuffer::create({&rb.sampleCopy}, nullptr, "readback.msaa_sample");
    }
    int const glY = t.height - y0 - h;  // GL rows run bottom to top
    glBindFramebuffer(GL_FRAMEBUFFER, rb.sampleFbo.id());
    glViewport(x0, glY, w, h);
    apply(kDecodeState);
    gl::Program const& p = r.shaders.variant(ProgramId::TexelCopy, "GBL_MSAA_SAMPLE_COPY");
    p.use();
    p.set("uWriteConstant", 0);
    p.set("uSample", sample);
    bindTextureUnit(slot::BIND_READBACK_SOURCE, GL_TEXTURE_2D_MULTISAMPLE, source.id());
    r.triangle.draw();
    bindTextureUnit(slot::BIND_READBACK_SOURCE, GL_TEXTURE_2D_MULTISAMPLE, 0);
    glViewport(0, 0, t.width, t.height);
    FloatImage img{w, h, 4, std::vector<float>(std::size_t(w) * std::size_t(h) * 4)};
    glBindFramebuffer(GL_READ_FRAMEBUFFER, rb.sampleFbo.id());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(x0, glY, w, h, GL_RGBA, GL_FLOAT, img.pixels.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    std::size_t const row = std::size_t(w) * 4;
    for (int y = 0; y < h / 2; ++y)
        std::swap_ranges(img.pixels.begin() + std::ptrdiff_t(std::size_t(y) * row),
                         img.pixels.begin() + std::ptrdiff_t(std::size_t(y + 1) * row),
                         img.pixels.begin() + std::ptrdiff_t(std::size_t(h - 1 - y) * row));
    if (slot != GBufferSlot::Depth) return img;
    FloatImage depth{w, h, 1, std::vector<float>(img.pixels.size() / 4)};  // the depth in red
    for (std::size_t i = 0; i < depth.pixels.size(); ++i) depth.pixels[i] = img.pixels[i * 4];
    return depth;
}

int Renderer::msaaSampleCount() const {
    return impl_->targets.msaa.gbuffer.fbo ? impl_->targets.msaa.samples : 0;
}

double Renderer::complexPixelShare() const {
    FloatImage const mask = readAttachment(Attachment::ComplexPixels);
    if (mask.pixels.empty()) return 0.0;
    std::size_t complex = 0;
    for (float v : mask.pixels) complex += v > 0.5f ? 1 : 0;
    return double(complex) / double(mask.pixels.size());
}

FloatImage Renderer::readViewTarget(ViewTarget const& target) const {
    if (!target.texture) return {};
    return readFramebuffer(target.fbo.id(), GL_COLOR_ATTACHMENT0, target.texture.width(), target.texture.height(), 4);
}

void readPixelColor(GLuint fbo, GLenum attachment, int x, int glY, glm::vec4& out) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glReadBuffer(attachment);
#ifdef __EMSCRIPTEN__
    std::vector<float> const rgba = readRgbaAsFloats(attachment, x, glY, 1, 1);
    out = glm::vec4(rgba[0], rgba[1], rgba[2], rgba[3]);
#else
    glReadPixels(x, glY, 1, 1, GL_RGBA, GL_FLOAT, &out[0]);
#endif
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

namespace {
// The pixel inspector's values of the layout's G-buffer at x, glY (GL's bottom-left origin).
void sampleGBufferPixel(ReadbackContext const& r, int x, int glY, glm::mat4 const& invViewProj, PixelSample& s) {
    RenderTargets const& t = r.targets;
    auto readColor = [&](GLuint fbo, GLenum attachment, glm::vec4& out) {
        readPixelColor(fbo, attachment, x, glY, out);
    };
    GBufferLayoutDesc const& desc = layoutDesc(t.gbuffer.layout);
    // Position and normal as the lighting decoded them, through a one-pixel decode pass.
    DecodedGBuffer const d = decodeGBuffer(r, {x, glY}, 1, 1, invViewProj);
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
#ifdef __EMSCRIPTEN__
    // WebGL2 reads neither depth nor stencil: both through their passes, over this pixel alone.
    s.depth = readDepthOrStencil(r, false, {x, glY, 1, 1})[0];
    s.stencil = std::uint8_t(readDepthOrStencil(r, true, {x, glY, 1, 1})[0]);
#else
    glBindFramebuffer(GL_READ_FRAMEBUFFER, t.gbuffer.fbo.id());
    glReadPixels(x, glY, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &s.depth);
    std::uint8_t stencil = 0;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(x, glY, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &stencil);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    s.stencil = stencil;
#endif
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    s.covered = s.position.w > 0.0f;
    // World position rebuilt from depth: unproject the pixel centre through the inverse view-projection.
    s.reconstructedPosition = worldFromDepth(invViewProj, {x, glY}, {t.width, t.height}, s.depth);
}
}  // namespace

PixelSample Renderer::samplePixel(int x, int y, Camera const& camera) const {
    RenderTargets const& t = impl_->targets;
    PixelSample s;
    if (t.empty() || x < 0 || y < 0 || x >= t.width || y >= t.height) return s;
    int const glY = t.height - 1 - y;
    auto readColor = [&](GLuint fbo, GLenum attachment, glm::vec4& out) {
        readPixelColor(fbo, attachment, x, glY, out);
    };
    float const aspect = float(t.width) / float(t.height);
    glm::mat4 const invViewProj = glm::inverse(camera.projection(aspect) * camera.view());
    if (impl_->thinGBuffer) {
        impl_->sampleThinPixel(x, glY, invViewProj, s);
    } else {
        sampleGBufferPixel(impl_->readbackContext(), x, glY, invViewProj, s);
    }
    readColor(t.litFbo.id(), GL_COLOR_ATTACHMENT0, s.lighting);
    if (impl_->coverageView) {
        glm::vec4 c{0.0f};
        readColor(t.coverageFbo.id(), GL_COLOR_ATTACHMENT0, c);
        s.coverage = glm::vec2(c);
        s.coverageView = impl_->coverageView;
        s.coverageMode = impl_->coverageMode;
    }
    return s;
}

}  // namespace gbl
