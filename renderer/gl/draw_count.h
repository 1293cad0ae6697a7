// Draw calls and compute dispatches the renderer has issued on this thread. Every glDraw* and
// glDispatchCompute call site in renderer/ counts itself here, so a pass's counts are the difference
// across it (PassScope, renderer_impl.h) and the Frame window, stats.json and bench show them.
// tests/draw_count_gl_test.cpp checks the counts of each mode's passes on a known scene, and that no
// call site in renderer/ is left out.
#pragma once

#include <cstdint>
#include <functional>

namespace gbl::gl {

struct DrawCount {
    std::uint64_t draws = 0;       // glDraw* calls (an instanced draw is one call)
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
inline void countDraw() {
    ++drawCount().draws;
    if (auto const& o = drawObserver()) o();
}
inline void countDispatch() {
    ++drawCount().dispatches;
}

}  // namespace gbl::gl
