// Time per pass: GL timestamps on drivers that attribute them, finish-bracketed CPU time on those that do not.
#pragma once

#include "gl/gl_api.h"
#include "gl/query.h"

#include <chrono>
#include <string>
#include <string_view>
#include <vector>

namespace gbl {

enum class TimingSource {
    GpuTimestamps,  // glQueryCounter(GL_TIMESTAMP) before and after each pass, read a frame later
    CpuFinish,      // glFinish before and after each pass, steady_clock in between
};

struct TimingMethod {
    TimingSource source = TimingSource::GpuTimestamps;
    std::string reason;  // one sentence: why this source, for stats.json and bench
};

inline std::string_view timingSourceName(TimingSource s) {
    return s == TimingSource::CpuFinish ? "cpu_finish" : "gpu_timestamps";
}

// Software rasterisers (Mesa's llvmpipe and softpipe, SwiftShader) bin draws and rasterise them
// at the next flush on their own threads; their timer queries measure when that work overlapped
// the query's bracket rather than the work issued inside it (a 58 s process once reported 55 s
// for geometry and 55 s for lighting). There the GL's "GPU" is the CPU, so a glFinish on each
// side of a pass makes the CPU wall time between them that pass's cost, and nothing else's.
// WebGL2 has no GL_TIMESTAMP queries (EXT_disjoint_timer_query_webgl2 is not used yet), so the browser
// build times passes on the CPU too.
inline TimingMethod chooseTimingMethod(std::string_view glRenderer) {
    if (gl::kWebGL2)
        return {TimingSource::CpuFinish,
                "WebGL2 has no GL_TIMESTAMP queries: each pass is bracketed by glFinish "
                "and timed on the CPU"};
    for (std::string_view soft : {"llvmpipe", "softpipe", "SwiftShader", "swrast"})
        if (glRenderer.find(soft) != std::string_view::npos)
            return {TimingSource::CpuFinish, std::string(soft) +
                                                 " rasterises on CPU threads after a flush and its timer queries "
                                                 "do not attribute work to passes: each pass is bracketed by "
                                                 "glFinish and timed on the CPU"};
    return {TimingSource::GpuTimestamps, "GL_TIMESTAMP queries at each pass boundary, read back a frame later"};
}

class GpuTimer {
public:
    // Chooses from the current context's GL_RENDERER at the first begin() unless forced (tests).
    void force(TimingSource source, std::string reason);
    TimingMethod const& method();

    void begin(std::string const& pass);
    void end();
    // Closes the frame. wait = true blocks until this frame's results exist (render/bench);
    // wait = false returns the latest finished frame's results (the editor). CPU timing always
    // has the current frame's results, since every pass ended with a glFinish.
    std::vector<std::pair<std::string, double>> finishFrame(bool wait);

private:
    struct Slot {
        std::string name;
        gl::Query start;  // timestamps
        gl::Query stop;
        double cpuMs = 0.0;
    };
    struct Frame {
        std::vector<Slot> slots;
        std::size_t used = 0;
        bool pending = false;
    };
    std::vector<std::pair<std::string, double>> read(Frame& f);

    bool chosen_ = false;
    TimingMethod method_;
    Frame frames_[2];
    int current_ = 0;
    bool open_ = false;
    std::chrono::steady_clock::time_point begun_;
    std::vector<std::pair<std::string, double>> last_;
};

}  // namespace gbl
