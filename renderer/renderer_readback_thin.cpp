// prepass's thin G-buffer read back (docs/deferred_lighting.md): after a prepass frame the
// G-buffer viewers, the pixel inspector and `render`'s export read it in the layout's place, which
// that frame never drew: normal and exponent from prepass.normal_exp, depth the lit depth, and
// position rebuilt from that depth as prepass's light pass rebuilds it.
#include "readback_io.h"

#include "core/depth.h"

namespace gbl {

bool thinGBufferReads(Attachment a) {
    return a == Attachment::Position || a == Attachment::Normal || a == Attachment::AlbedoSpec ||
           a == Attachment::Emissive || a == Attachment::Depth;
}

FloatImage RendererImpl::readThinAttachment(Attachment a) {
    RenderTargets const& t = targets;
    FloatImage const depth = readDepthImage(readbackContext(), t.litFbo.id(), t.litDepth);
    if (a == Attachment::Depth) return depth;
    std::size_t const pixels = std::size_t(t.width) * std::size_t(t.height);
    // Zero where nothing was drawn (alpha 0, as the decoded G-buffer reads), and all of Emissive:
    // the thin G-buffer stores no emission or occlusion (the second geometry pass reads them).
    FloatImage out{t.width, t.height, 4, std::vector<float>(pixels * 4, 0.0f)};
    if (a == Attachment::Emissive) return out;
    FloatImage const stored = a == Attachment::Position
                                  ? FloatImage{}
                                  : readFramebuffer(t.prepassFbo.id(), GL_COLOR_ATTACHMENT0, t.width, t.height, 4);
    for (int y = 0; y < t.height; ++y) {
        for (int x = 0; x < t.width; ++x) {
            std::size_t const i = std::size_t(y) * std::size_t(t.width) + std::size_t(x);
            float const d = depth.pixels[i];
            if (!(d < 1.0f)) continue;  // cleared to the far plane: background
            float* o = &out.pixels[i * 4];
            if (a == Attachment::Position) {
                glm::vec3 const p = worldFromDepth(frameInverseViewProj, {x, t.height - 1 - y}, {t.width, t.height}, d);
                o[0] = p.x, o[1] = p.y, o[2] = p.z, o[3] = 1.0f;
            } else if (a == Attachment::Normal) {
                o[0] = stored.pixels[i * 4], o[1] = stored.pixels[i * 4 + 1], o[2] = stored.pixels[i * 4 + 2];
                o[3] = 1.0f;
            } else {  // AlbedoSpec: no albedo stored; the alpha, the specular viewer's, is the exponent
                o[3] = stored.pixels[i * 4 + 3];
            }
        }
    }
    return out;
}

void RendererImpl::sampleThinPixel(int x, int glY, glm::mat4 const& inverseViewProj, PixelSample& s) {
    RenderTargets const& t = targets;
    s.thinGBuffer = true;
    s.depth = readDepthTexel(readbackContext(), t.litFbo.id(), t.litDepth, x, glY);
    s.covered = s.depth < 1.0f;
    readPixelColor(t.prepassFbo.id(), GL_COLOR_ATTACHMENT0, x, glY, s.rawNormal);
    s.reconstructedPosition = worldFromDepth(inverseViewProj, {x, glY}, {t.width, t.height}, s.depth);
    s.emissiveAo = glm::vec4(0.0f);
    if (!s.covered) return;  // the background: zeros, as readThinAttachment reads it
    s.position = glm::vec4(s.reconstructedPosition, 1.0f);
    s.normal = glm::vec4(glm::vec3(s.rawNormal), 1.0f);
    s.albedoSpec = glm::vec4(0.0f, 0.0f, 0.0f, s.rawNormal.w);
}

}  // namespace gbl
