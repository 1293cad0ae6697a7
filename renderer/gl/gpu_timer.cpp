// Pass timer bookkeeping: one pair of timestamps (or one CPU interval) per pass.
#include "gl/gpu_timer.h"

namespace gbl {

void GpuTimer::force(TimingSource source, std::string reason) {
    method_ = {source, std::move(reason)};
    chosen_ = true;
}

TimingMethod const& GpuTimer::method() {
    if (!chosen_) {
        auto const* r = reinterpret_cast<char const*>(glGetString(GL_RENDERER));
        method_ = chooseTimingMethod(r ? r : "");
        chosen_ = true;
    }
    return method_;
}

void GpuTimer::begin(std::string const& pass) {
    if (open_) end();
    bool const cpu = method().source == TimingSource::CpuFinish;
    Frame& f = frames_[current_];
    if (f.used == f.slots.size()) {
        Slot s{pass, {}, {}, 0.0};
        if (!cpu) {
            s.start = gl::Query::create(GL_TIMESTAMP, "pass start");
            s.stop = gl::Query::create(GL_TIMESTAMP, "pass end");
        }
        f.slots.push_back(std::move(s));
    }
    Slot& s = f.slots[f.used++];
    s.name = pass;
    if (cpu) {
        glFinish();  // earlier passes' work must not land in this one
        begun_ = std::chrono::steady_clock::now();
    } else {
        if (!s.start) {  // slots made while timing on the CPU (a forced switch)
            s.start = gl::Query::create(GL_TIMESTAMP, "pass start");
            s.stop = gl::Query::create(GL_TIMESTAMP, "pass end");
        }
        glQueryCounter(s.start.id(), GL_TIMESTAMP);
    }
    open_ = true;
}

void GpuTimer::end() {
    if (!open_) return;
    Slot& s = frames_[current_].slots[frames_[current_].used - 1];
    if (method().source == TimingSource::CpuFinish) {
        glFinish();
        s.cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begun_).count();
    } else {
        glQueryCounter(s.stop.id(), GL_TIMESTAMP);
    }
    open_ = false;
}

std::vector<std::pair<std::string, double>> GpuTimer::read(Frame& f) {
    std::vector<std::pair<std::string, double>> out;
    bool const cpu = method().source == TimingSource::CpuFinish;
    for (std::size_t i = 0; i < f.used; ++i) {
        Slot const& s = f.slots[i];
        double ms = s.cpuMs;
        if (!cpu) {
            GLuint64 const a = s.start.result(), b = s.stop.result();
            ms = b > a ? double(b - a) * 1e-6 : 0.0;
        }
        out.emplace_back(s.name, ms);
    }
    f.used = 0;
    f.pending = false;
    return out;
}

std::vector<std::pair<std::string, double>> GpuTimer::finishFrame(bool wait) {
    if (open_) end();
    Frame& cur = frames_[current_];
    cur.pending = cur.used > 0;
    if (wait || method().source == TimingSource::CpuFinish) {
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
