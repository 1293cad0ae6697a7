// GPU time per pass from GL_TIME_ELAPSED queries, double-buffered so the editor never stalls.
#pragma once

#include "gl/query.h"

#include <chrono>
#include <string>
#include <vector>

namespace gbl {

class GpuTimer {
public:
    void begin(std::string const& pass);
    void end();
    // Closes the frame. wait = true blocks until this frame's results exist (render/bench);
    // wait = false returns the latest finished frame's results (the editor).
    std::vector<std::pair<std::string, double>> finishFrame(bool wait);

private:
    struct Slot {
        std::string name;
        gl::Query query;
        std::chrono::steady_clock::time_point begun;
    };
    struct Frame {
        std::vector<Slot> slots;
        std::size_t used = 0;
        bool pending = false;
    };
    Frame frames_[2];
    int current_ = 0;
    bool open_ = false;
    std::vector<std::pair<std::string, double>> last_;
};

}  // namespace gbl
