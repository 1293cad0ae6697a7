// msaa (docs/msaa.md): the samples of the multisampled G-buffer decoded as the lighting reads them,
// one sample of one attachment or the samples-that-differ count of every pixel, both through the
// decode pass's msaa variants (shaders/gbuffer_decode.frag), so every layout is decoded alike.
#include "renderer_impl.h"

#include "passes/gbuffer_decode.h"

#include <algorithm>
#include <vector>

namespace gbl {

namespace {

// `rect` (top-left origin) clipped to the frame, in GL's bottom-left rows; zero size outside it.
glm::ivec4 glRect(glm::ivec4 rect, int width, int height) {
    int const x0 = std::clamp(rect.x, 0, width), y0 = std::clamp(rect.y, 0, height);
    int const w = std::clamp(rect.z, 0, width - x0), h = std::clamp(rect.w, 0, height - y0);
    return {x0, height - y0 - h, w, h};
}

}  // namespace

FloatImage Renderer::readMsaaDecodedSample(GBufferSlot slot, int sample) {
    return readMsaaDecodedSample(slot, sample, {0, 0, width(), height()});
}

// The decode target is the rectangle's size: the inspector's pixel costs one pixel's decode.
FloatImage Renderer::readMsaaDecodedSample(GBufferSlot slot, int sample, glm::ivec4 rect) {
    RendererImpl& r = *impl_;
    RenderTargets const& t = r.targets;
    if (!t.msaa.gbuffer.fbo || slot == GBufferSlot::Depth || sample < 0 || sample >= t.msaa.samples) return {};
    glm::ivec4 const at = glRect(rect, t.width, t.height);
    if (at.z <= 0 || at.w <= 0) return {};
    DecodedGBuffer const d = createDecodedGBuffer(at.z, at.w, true);
    GBufferDecodeConfig c{r.frameInverseViewProj, {at.x, at.y}, std::span(&kDecodeState, 1)};
    c.sample = sample;
    gbufferDecodePass({gbufferTextures(t.msaa.gbuffer), r.msaaProgram("", ProgramId::GBufferDecode), r.triangle, d}, c);
    int const index = slot == GBufferSlot::Position     ? 0
                      : slot == GBufferSlot::Normal     ? 1
                      : slot == GBufferSlot::AlbedoSpec ? 2
                                                        : 3;
    return readFramebuffer(d.fbo.id(), GLenum(GL_COLOR_ATTACHMENT0 + index), at.z, at.w, 4);
}

std::vector<glm::vec2> Renderer::msaaSamplePositions() const {
    return impl_->targets.msaa.gbuffer.fbo ? impl_->targets.msaa.samplePositions : std::vector<glm::vec2>{};
}

FloatImage Renderer::msaaDistinctSampleCounts(glm::vec3 eye) {
    RendererImpl& r = *impl_;
    RenderTargets const& t = r.targets;
    if (!t.msaa.gbuffer.fbo || t.msaa.samples <= 0 || t.empty()) return {};
    DecodedGBuffer const d = createDecodedGBuffer(t.width, t.height);
    GBufferDecodeConfig c{r.frameInverseViewProj, {0, 0}, std::span(&kDecodeState, 1)};
    c.eye = eye;
    gbufferDecodePass(
        {gbufferTextures(t.msaa.gbuffer), r.msaaProgram("COUNTS", ProgramId::GBufferDecode), r.triangle, d}, c);
    FloatImage const rgba = readFramebuffer(d.fbo.id(), GL_COLOR_ATTACHMENT0, t.width, t.height, 4);
    FloatImage counts{t.width, t.height, 1, std::vector<float>(rgba.pixels.size() / 4)};
    for (std::size_t i = 0; i < counts.pixels.size(); ++i) counts.pixels[i] = rgba.pixels[i * 4];
    return counts;
}

}  // namespace gbl
