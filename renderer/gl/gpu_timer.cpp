// Timer query bookkeeping.
#include "gl/gpu_timer.h"

#include <algorithm>

namespace gbl {

void GpuTimer::begin(std::string const& pass) {
    Frame& f = frames_[current_];
    if (f.used == f.slots.size()) f.slots.push_back({pass, gl::Query::create(GL_TIME_ELAPSED, "pass timer"), {}});
    Slot& s = f.slots[f.used++];
    s.name = pass;
    s.begun = std::chrono::steady_clock::now();
    s.query.begin();
    open_ = true;
}

void GpuTimer::end() {
    if (!open_) return;
    // Software rasterisers (llvmpipe) bin draws and rasterise at the next flush; without one
    // a pass's work is billed to whichever query is open when the flush happens.
    glFlush();
    glEndQuery(GL_TIME_ELAPSED);
    open_ = false;
}

std::vector<std::pair<std::string, double>> GpuTimer::finishFrame(bool wait) {
    auto read = [](Frame& f) {
        std::vector<std::pair<std::string, double>> out;
        auto const now = std::chrono::steady_clock::now();
        for (std::size_t i = 0; i < f.used; ++i) {
            double const gpuMs = double(f.slots[i].query.result()) * 1e-6;
            // A pass cannot take longer on the GPU than the wall time from its start to now.
            // Mesa's llvmpipe sometimes reports the clock's absolute value for the first query
            // after a read-back; the bound keeps such a value from swamping the statistics.
            double const wallMs = std::chrono::duration<double, std::milli>(now - f.slots[i].begun).count();
            out.emplace_back(f.slots[i].name, std::min(gpuMs, wallMs));
        }
        f.used = 0;
        f.pending = false;
        return out;
    };
    Frame& cur = frames_[current_];
    cur.pending = cur.used > 0;
    if (wait) {
        last_ = read(cur);
        return last_;
    }
    Frame& prev = frames_[1 - current_];
    // The previous frame was submitted a whole frame ago, so reading it rarely waits, and the
    // reported times lag by exactly one frame.
    if (prev.pending) last_ = read(prev);
    current_ = 1 - current_;
    return last_;
}

}  // namespace gbl
