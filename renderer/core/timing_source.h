// How a frame's pass times were taken (gl/gpu_timer.h chooses), by name: the Stats window, stats.json
// and bench read it without the GL layer.
#pragma once

#include <string>
#include <string_view>

namespace gbl {

#ifdef __EMSCRIPTEN__
inline constexpr bool kBrowserBuild = true;
#else
inline constexpr bool kBrowserBuild = false;
#endif

enum class TimingSource {
    GpuTimestamps,  // glQueryCounter(GL_TIMESTAMP) before and after each pass, read a frame later
    CpuFinish,      // glFinish before and after each pass, steady_clock in between
    GpuElapsed,     // a GL_TIME_ELAPSED query around each pass (WebGL2's EXT_disjoint_timer_query_webgl2)
};

struct TimingMethod {
    TimingSource source = TimingSource::GpuTimestamps;
    std::string reason;  // one sentence: why this source, for stats.json and bench
};

inline std::string_view timingSourceName(TimingSource s) {
    switch (s) {
        case TimingSource::CpuFinish:
            return "cpu_finish";
        case TimingSource::GpuElapsed:
            return "gpu_elapsed";
        case TimingSource::GpuTimestamps:
            break;
    }
    return "gpu_timestamps";
}

// Whether pass times from `timingSource` (FrameStats::timingSource) measure the passes: not so
// in a browser without timer queries, where the CPU times stand for nothing drawn.
inline bool passesTimed(std::string_view timingSource) {
    return !(kBrowserBuild && timingSource == timingSourceName(TimingSource::CpuFinish));
}

}  // namespace gbl
