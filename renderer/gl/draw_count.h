// Draw calls and compute dispatches the renderer has issued on this thread. Every glDraw* and
// glDispatchCompute call site in renderer/ counts itself here, so a pass's counts are the difference
// across it (PassScope, renderer_impl.h) and the Frame window, stats.json and bench show them.
// tests/draw_count_gl_test.cpp checks the counts of each mode's passes on a known scene, and that no
// call site in renderer/ is left out.
#pragma once

#include <cstdint>

namespace gbl::gl {

struct DrawCount {
    std::uint64_t draws = 0;       // glDraw* calls (an instanced draw is one call)
    std::uint64_t dispatches = 0;  // glDispatchCompute calls
};

inline DrawCount& drawCount() {
    static thread_local DrawCount count;
    return count;
}
inline void countDraw() {
    ++drawCount().draws;
}
inline void countDispatch() {
    ++drawCount().dispatches;
}

}  // namespace gbl::gl
