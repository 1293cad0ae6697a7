// Time per pass: GL timestamps on drivers that attribute them, finish-bracketed CPU time on those that do not.
#pragma once

#include "core/timing_source.h"
#include "gl/gl_api.h"
#include "gl/query.h"

#include <chrono>
#include <string>
#include <string_view>
#include <vector>

namespace gbl {

// Software rasterisers (Mesa's llvmpipe and softpipe, SwiftShader) bin draws and rasterise them
// at the next flush on their own threads; their timer queries measure when that work overlapped
// the query's bracket rather than the work issued inside it (a 58 s process once reported 55 s
// for geometry and 55 s for lighting). There the GL's "GPU" is the CPU, so a glFinish on each
// side of a pass makes the CPU wall time between them that pass's cost, and nothing else's.
// In the browser the passes run in the browser's GPU process, whatever it draws with (SwiftShader
// included); its timer queries (EXT_disjoint_timer_query_webgl2, where offered) bracket each pass
// there. Without them nothing on the page can time a pass: WebGL's finish() returns before the
// GPU process has drawn, so the CPU times below are kept only to name the passes.
inline TimingMethod chooseTimingMethod(std::string_view glRenderer, bool browserTimerQueries = false) {
    if (gl::kWebGL2)
        return browserTimerQueries
                   ? TimingMethod{TimingSource::GpuElapsed,
                                  "EXT_disjoint_timer_query_webgl2: a GL_TIME_ELAPSED query around each pass, "
                                  "read when the browser has its result (a frame or more later)"}
                   : TimingMethod{TimingSource::CpuFinish,
                                  "this browser does not offer EXT_disjoint_timer_query_webgl2, and WebGL's "
                                  "finish() returns before the GPU process has drawn: passes are not timed"};
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
    // wait = false returns the results of the newest finished frame of the same `stream` (the
    // editor), without waiting: a frame's queries are read once the GL has their results, and
    // until then the stream's earlier figures stand. Streams keep frames that alternate apart
    // (the A/B view renders side B, then side A, every frame: streams 1 and 0). CPU timing always
    // has the current frame's results, since every pass ended with a glFinish. In WebGL a query's
    // result never exists before the page returns to the browser, so there nothing waits.
    std::vector<std::pair<std::string, double>> finishFrame(bool wait, int stream = 0);

    static constexpr int kStreams = 2;

private:
    struct Slot {
        std::string name;
        gl::Query start;  // timestamps; GpuElapsed: the pass's GL_TIME_ELAPSED query
        gl::Query stop;
        double cpuMs = 0.0;
    };
    struct Frame {
        std::vector<Slot> slots;
        std::size_t used = 0;
        bool pending = false;
        int stream = 0;
        long serial = 0;  // the order frames were closed in
    };
    std::vector<std::pair<std::string, double>> read(Frame& f);
    bool ready(Frame const& f);
    gl::Query makeQuery(char const* label) const;

    bool chosen_ = false;
    TimingMethod method_;
    // Frames in flight: two streams, each with a frame being read and up to two waiting.
    Frame frames_[6];
    int current_ = 0;
    long serial_ = 0;
    bool open_ = false;
    std::chrono::steady_clock::time_point begun_;
    std::vector<std::pair<std::string, double>> last_[kStreams];
};

}  // namespace gbl
