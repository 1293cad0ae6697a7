// The lookup from declared resources to the render targets.
#include "gpu/frame_resources.h"

#include "gpu/draw_state_gl.h"

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace gbl {

namespace {

bool isGBufferColor(Resource r) {
    return r == Resource::GBufferPosition || r == Resource::GBufferNormal || r == Resource::GBufferAlbedoSpec ||
           r == Resource::GBufferEmissive;
}

bool isMsaaColor(Resource r) {
    return r == Resource::MsaaPosition || r == Resource::MsaaNormal || r == Resource::MsaaAlbedoSpec ||
           r == Resource::MsaaEmissive;
}

[[noreturn]] void noTarget(std::string const& what) {
    throw std::logic_error("FrameResources: " + what + "; give it a target in gpu/render_targets.h");
}

}  // namespace

GBufferTextures gbufferTextures(GBuffer const& g) {
    return {g.position, g.normal, g.albedoSpec, g.emissive, g.depth};
}

gl::Framebuffer const& FrameResources::blitSource(Resource depth) const {
    switch (depth) {
        case Resource::GBufferDepth:
            return targets.gbuffer.fbo;
        case Resource::LitDepth:
            return targets.litFbo;
        case Resource::MsaaDepth:
            return targets.msaa.gbuffer.fbo;
        default:
            break;
    }
    noTarget("no framebuffer to blit " + std::string(resourceName(depth)) + " from");
}

gl::Texture const& FrameResources::texture(Resource r) const {
    RenderTargets const& t = targets;
    switch (r) {
        case Resource::GBufferPosition:
            return t.gbuffer.position;
        case Resource::GBufferNormal:
            return t.gbuffer.normal;
        case Resource::GBufferAlbedoSpec:
            return t.gbuffer.albedoSpec;
        case Resource::GBufferEmissive:
            return t.gbuffer.emissive;
        case Resource::GBufferDepth:
            return t.gbuffer.depth;
        case Resource::VolumeDepth:
            return t.volumeDepthStencil();
        case Resource::Lighting:
            return t.lighting;
        case Resource::LitDepth:
            return t.litDepth;
        case Resource::DiffuseLight:
            return t.diffuseLight;
        case Resource::SpecularLight:
            return t.specularLight;
        case Resource::Coverage:
            return t.coverage;
        case Resource::Display:
            return t.display;
        case Resource::MsaaPosition:
            return t.msaa.gbuffer.position;
        case Resource::MsaaNormal:
            return t.msaa.gbuffer.normal;
        case Resource::MsaaAlbedoSpec:
            return t.msaa.gbuffer.albedoSpec;
        case Resource::MsaaEmissive:
            return t.msaa.gbuffer.emissive;
        case Resource::MsaaDepth:
            return t.msaa.gbuffer.depth;
        case Resource::ComplexMask:
            return t.msaa.complexMask;
        case Resource::PrepassNormal:
            return t.prepassNormal;
        default:
            break;
    }
    noTarget(std::string(resourceName(r)) + " is no render target texture");
}

gl::Framebuffer const& FrameResources::framebuffer(std::span<Resource const> color,
                                                   std::optional<Resource> depth) const {
    RenderTargets const& t = targets;
    bool const volumeDepth = depth == Resource::VolumeDepth || depth == Resource::GBufferDepth;
    if (!color.empty()) {
        Resource const first = color.front();
        if (isGBufferColor(first)) return t.gbuffer.fbo;
        if (isMsaaColor(first)) return t.msaa.gbuffer.fbo;
        if (first == Resource::ComplexMask) return t.msaa.complexFbo;
        if (first == Resource::Lighting) return volumeDepth ? t.volumeFbo : t.litFbo;
        if (first == Resource::DiffuseLight) return volumeDepth ? t.splitVolumeFbo : t.splitFbo;
        if (first == Resource::Coverage) return t.coverageFbo;
        if (first == Resource::PrepassNormal) return t.prepassFbo;
        if (first == Resource::Display) {
            if (!depth) return t.displayFbo;
            return depth == Resource::LitDepth ? t.overlayFbo : t.overlayGBufferDepthFbo;
        }
        if (first == Resource::View && view) return *view;
    }
    noTarget("no framebuffer attaches " +
             (color.empty() ? std::string("no colour") : std::string(resourceName(color.front()))));
}

void FrameResources::clear(std::span<Resource const> resources) const {
    std::vector<std::pair<GLuint, GLbitfield>> clears;  // each framebuffer once, in the order first named
    auto add = [&](gl::Framebuffer const& fbo, GLbitfield bits) {
        for (auto& c : clears)
            if (c.first == fbo.id()) {
                c.second |= bits;
                return;
            }
        clears.emplace_back(fbo.id(), bits);
    };
    GLbitfield const depthStencil = GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT;
    for (Resource r : resources) {
        if (isGBufferColor(r))
            add(targets.gbuffer.fbo, GL_COLOR_BUFFER_BIT);
        else if (r == Resource::GBufferDepth)
            add(targets.gbuffer.fbo, depthStencil);
        else if (isMsaaColor(r))
            add(targets.msaa.gbuffer.fbo, GL_COLOR_BUFFER_BIT);
        else if (r == Resource::MsaaDepth)
            add(targets.msaa.gbuffer.fbo, depthStencil);
        else if (r == Resource::ComplexMask)
            add(targets.msaa.complexFbo, GL_COLOR_BUFFER_BIT);
        else if (r == Resource::Lighting)
            add(targets.litFbo, GL_COLOR_BUFFER_BIT);
        else if (r == Resource::LitDepth)
            add(targets.litFbo, depthStencil);
        else if (r == Resource::DiffuseLight || r == Resource::SpecularLight)
            add(targets.splitFbo, GL_COLOR_BUFFER_BIT);
        else if (r == Resource::Coverage)
            add(targets.coverageFbo, GL_COLOR_BUFFER_BIT);
        else if (r == Resource::PrepassNormal)
            add(targets.prepassFbo, GL_COLOR_BUFFER_BIT);
        else if (r == Resource::Display)
            add(targets.displayFbo, GL_COLOR_BUFFER_BIT);
        else
            noTarget("cannot clear " + std::string(resourceName(r)));
    }
    for (auto const& [fbo, bits] : clears) clearFramebuffer(fbo, bits);
}

}  // namespace gbl
