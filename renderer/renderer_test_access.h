// TEST ONLY: what a test may do to a Renderer that no caller of the renderer may. Never
// included by the renderer's users (app/, ui/).
#pragma once

#include "renderer.h"

#include <cstddef>
#include <functional>

namespace gbl {

struct RendererTestAccess {
    // Runs `hook` inside every later render() call, between the geometry and lighting passes
    // (an empty function removes it). The GL error tests raise an error there.
    static void setFrameHook(Renderer& renderer, std::function<void()> hook);
    // Off: every view is drawn by the one view program that switches on uView at each pixel, as
    // before the views had programs of their own (RendererImpl::viewProgram). On by default.
    static void setViewVariants(Renderer& renderer, bool on);
    // Shader programs the renderer has built so far.
    static std::size_t shaderBuilds(Renderer& renderer);
};

}  // namespace gbl
