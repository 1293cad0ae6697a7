// What each declared Resource (core/frame_passes.h) is on the GPU: the one lookup from a pass's
// declaration to the textures and framebuffers the executor hands it.
#pragma once

#include "core/frame_passes.h"
#include "gpu/render_targets.h"

#include <optional>
#include <span>

namespace gbl {

struct FrameResources {
    RenderTargets const& targets;
    gl::Framebuffer const* view = nullptr;  // Resource::View: Renderer::drawView's target

    // The texture behind `r`; throws for a resource that is no screen-sized texture (lights, lists).
    gl::Texture const& texture(Resource r) const;
    // The framebuffer that attaches `color` and `depthStencil`, as a raster or blit pass declares them;
    // throws when no target attaches that combination (a declaration with no framebuffer behind it).
    gl::Framebuffer const& framebuffer(std::span<Resource const> color, std::optional<Resource> depthStencil) const;
    gl::Framebuffer const& framebuffer(PassDecl const& p) const { return framebuffer(p.color, p.depthStencil); }
    // Clears `resources` (PassDecl::clears): colour to zero, depth to 1, stencil to 0, each framebuffer once.
    void clear(std::span<Resource const> resources) const;
};

}  // namespace gbl
