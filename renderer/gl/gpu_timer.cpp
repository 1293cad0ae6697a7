// Pass timer bookkeeping: one pair of timestamps, one elapsed-time query or one CPU interval per pass.
#include "gl/gpu_timer.h"

#include <algorithm>

#ifndef GL_GPU_DISJOINT_EXT
#define GL_GPU_DISJOINT_EXT 0x8FBB
#endif

namespace gbl {

void GpuTimer::force(TimingSource source, std::string reason) {
    method_ = {source, std::move(reason)};
    chosen_ = true;
}

TimingMethod const& GpuTimer::method() {
    if (!chosen_) {
        auto const* r = reinterpret_cast<char const*>(glGetString(GL_RENDERER));
        method_ = chooseTimingMethod(r ? r : "", gl::kWebGL2 && gl::hasExtension("EXT_disjoint_timer_query_webgl2"));
        chosen_ = true;
    }
    return method_;
}

gl::Query GpuTimer::makeQuery(char const* label) const {
    return gl::Query::create(method_.source == TimingSource::GpuElapsed ? GL_TIME_ELAPSED : GL_TIMESTAMP, label);
}

void GpuTimer::begin(std::string const& pass) {
    if (open_) end();
    TimingSource const source = method().source;
    Frame& f = frames_[current_];
    if (f.used == f.slots.size()) f.slots.push_back(Slot{pass, {}, {}, 0.0});
    Slot& s = f.slots[f.used++];
    s.name = pass;
    if (source == TimingSource::CpuFinish) {
        glFinish();  // earlier passes' work must not land in this one
        begun_ = std::chrono::steady_clock::now();
    } else {
        // Slots made while timing on the CPU (a forced switch) get their queries here.
        if (!s.start) s.start = makeQuery("pass start");
        if (source == TimingSource::GpuElapsed) {
            glBeginQuery(GL_TIME_ELAPSED, s.start.id());
        } else {
            if (!s.stop) s.stop = makeQuery("pass end");
            glQueryCounter(s.start.id(), GL_TIMESTAMP);
        }
    }
    open_ = true;
}

void GpuTimer::end() {
    if (!open_) return;
    Slot& s = frames_[current_].slots[frames_[current_].used - 1];
    switch (method().source) {
        case TimingSource::CpuFinish:
            glFinish();
            s.cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begun_).count();
            break;
        case TimingSource::GpuElapsed:
            glEndQuery(GL_TIME_ELAPSED);
            break;
        case TimingSource::GpuTimestamps:
            glQueryCounter(s.stop.id(), GL_TIMESTAMP);
            break;
    }
    open_ = false;
}

bool GpuTimer::ready(Frame const& f) {
    if (f.used == 0) return true;
    // A frame's queries finish in order: its last one stands for all.
    Slot const& last = f.slots[f.used - 1];
    return (method().source == TimingSource::GpuElapsed ? last.start : last.stop).resultAvailable();
}

std::vector<std::pair<std::string, double>> GpuTimer::read(Frame& f) {
    std::vector<std::pair<std::string, double>> out;
    TimingSource const source = method().source;
    for (std::size_t i = 0; i < f.used; ++i) {
        Slot const& s = f.slots[i];
        double ms = s.cpuMs;
        if (source == TimingSource::GpuElapsed) {
            ms = double(s.start.result()) * 1e-6;
        } else if (source == TimingSource::GpuTimestamps) {
            GLuint64 const a = s.start.result(), b = s.stop.result();
            ms = b > a ? double(b - a) * 1e-6 : 0.0;
        }
        out.emplace_back(s.name, ms);
    }
    f.used = 0;
    f.pending = false;
    return out;
}

std::vector<std::pair<std::string, double>> GpuTimer::finishFrame(bool wait, int stream) {
    if (open_) end();
    stream = std::clamp(stream, 0, kStreams - 1);
    TimingSource const source = method().source;
    Frame& cur = frames_[current_];
    cur.pending = cur.used > 0;
    cur.stream = stream;
    cur.serial = ++serial_;
    auto& last = last_[stream];
    // WebGL never has a result before the page returns to the browser: a wait there would never end.
    if (source == TimingSource::CpuFinish || (wait && !gl::kWebGL2)) {
        last = read(cur);
        return last;
    }
    // The newest frame of this stream whose results exist; its older ones are dropped unread.
    Frame* newest = nullptr;
    for (Frame& f : frames_)
        if (f.pending && f.stream == stream && ready(f) && (!newest || f.serial > newest->serial)) newest = &f;
    if (newest) {
        for (Frame& f : frames_)
            if (f.pending && f.stream == stream && f.serial < newest->serial) {
                f.used = 0;
                f.pending = false;
            }
        auto times = read(*newest);
        // The GPU's clock jumped (power state, context switch) while WebGL's queries ran: their
        // figures mean nothing, and the ones before stand.
        GLint disjoint = 0;
        if (gl::kWebGL2 && source == TimingSource::GpuElapsed) glGetIntegerv(GL_GPU_DISJOINT_EXT, &disjoint);
        if (!disjoint) last = std::move(times);
    }
    // The next frame goes to a free slot; with every one still waiting, the oldest is dropped.
    int next = -1;
    for (int i = 0; i < int(std::size(frames_)); ++i)
        if (!frames_[i].pending) {
            next = i;
            break;
        }
    if (next < 0) {
        next = 0;
        for (int i = 1; i < int(std::size(frames_)); ++i)
            if (frames_[i].serial < frames_[next].serial) next = i;
        frames_[next].used = 0;
        frames_[next].pending = false;
    }
    current_ = next;
    return last;
}

}  // namespace gbl
