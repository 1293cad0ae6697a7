// What each declared Resource (core/frame_passes.h) is on the GPU: the one lookup from a pass's
// declaration to the textures and framebuffers the executor hands it.
#pragma once

#include "core/frame_passes.h"
#include "gpu/render_targets.h"

#include <optional>
#include <span>

namespace gbl {

// The G-buffer's textures as a pass samples them (the declared GBuffer* resources, resolved): a
// layout that rebuilds position from depth has an empty `position`, one without emission an empty
// `emissive`.
struct GBufferTextures {
    gl::Texture const& position;
    gl::Texture const& normal;
    gl::Texture const& albedoSpec;
    gl::Texture const& emissive;
    gl::Texture const& depth;  // the depth-stencil
};
GBufferTextures gbufferTextures(GBuffer const& gbuffer);

struct FrameResources {
    RenderTargets const& targets;
    gl::Framebuffer const* view = nullptr;  // Resource::View: Renderer::drawView's target

    // The texture behind `r`; throws for a resource that is no screen-sized texture (lights, lists).
    gl::Texture const& texture(Resource r) const;
    // The framebuffer that attaches `color` and `depthStencil`, as a raster or blit pass declares them;
    // throws when no target attaches that combination (a declaration with no framebuffer behind it).
    gl::Framebuffer const& framebuffer(std::span<Resource const> color, std::optional<Resource> depthStencil) const;
    gl::Framebuffer const& framebuffer(PassDecl const& p) const { return framebuffer(p.color, p.depthStencil); }
    // The G-buffer's textures (Resource::GBuffer*), for the passes that sample them.
    GBufferTextures gbuffer() const { return gbufferTextures(targets.gbuffer); }
    // The framebuffer a blit reads the depth-stencil `depth` from (a blit pass's declared sample);
    // throws for a resource no framebuffer attaches as its depth.
    gl::Framebuffer const& blitSource(Resource depth) const;
    // Clears `resources` (PassDecl::clears): colour to zero, depth to 1, stencil to 0, each framebuffer once.
    void clear(std::span<Resource const> resources) const;
};

}  // namespace gbl
