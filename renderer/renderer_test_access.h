// TEST ONLY: what a test may do to a Renderer that no caller of the renderer may. Never
// included by the renderer's users (app/, ui/).
#pragma once

#include "pass_run.h"
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
    // Calls `observer` with each pass's declaration just before the executor runs it (render() and
    // drawView); an empty function removes it.
    static void setPassObserver(Renderer& renderer, std::function<void(PassDecl const&)> observer);
    // Lets `edit` change each later frame's declared passes before they run (tests that show a
    // check fails on a declaration changed by hand); an empty function removes it.
    static void editDeclarations(Renderer& renderer, std::function<void(std::vector<PassDecl>&)> edit);
    // A pass of the test's own: `decl` (its customName set) runs after the pass `after` in every
    // later frame that runs `after`, through the same executor as the renderer's passes, with `run`.
    static void addPass(Renderer& renderer, PassId after, PassDecl decl, RunPass run);
    static void clearPasses(Renderer& renderer);  // removes every pass addPass added
    // Shader programs the renderer has built so far.
    static std::size_t shaderBuilds(Renderer& renderer);
};

}  // namespace gbl
