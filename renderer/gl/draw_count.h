// Draw calls, the triangles they drew and compute dispatches the renderer has issued on this thread.
// Every glDraw* and glDispatchCompute call site in renderer/ counts itself here, so a pass's counts
// are the difference across it (PassScope, renderer_impl.h) and the Frame window, the Stats window,
// stats.json and bench show them. Triangles are counted on the CPU at the call (indices / 3 times the
// instances), which works on every context (GL 3.3, WebGL2) where GL_PRIMITIVES_GENERATED does not.
// tests/draw_count_gl_test.cpp checks the counts of each mode's passes on a known scene, and that no
// call site in renderer/ is left out.
#pragma once

#include <cstdint>
#include <functional>

namespace gbl::gl {

struct DrawCount {
    std::uint64_t draws = 0;       // glDraw* calls (an instanced draw is one call)
    std::uint64_t triangles = 0;   // triangles those calls submitted, every instance's (lines: none)
    std::uint64_t dispatches = 0;  // glDispatchCompute calls
};

inline DrawCount& drawCount() {
    static thread_local DrawCount count;
    return count;
}
// TEST ONLY: called after every counted draw and dispatch, with the GL state the call ran under
// still set (tests/draw_state_gl_test.cpp reads it back there). Empty outside that test.
inline std::function<void()>& drawObserver() {
    static thread_local std::function<void()> observer;
    return observer;
}
// `triangles`: what the call submitted (GL_TRIANGLES: its vertex or index count / 3, times its instances).
inline void countDraw(std::uint64_t triangles) {
    ++drawCount().draws;
    drawCount().triangles += triangles;
    if (auto const& o = drawObserver()) o();
}
inline void countDispatch() {
    ++drawCount().dispatches;
}

}  // namespace gbl::gl
