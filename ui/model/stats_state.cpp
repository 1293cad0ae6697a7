// Frame history for the Stats window.
#include "model/stats_state.h"

#include <algorithm>

namespace gbl::ui {

void recordFrame(StatsState& stats, FrameStats const& frame, EditorCost const& cost) {
    stats.frameMs[std::size_t(stats.next)] = float(cost.frameCpuMs);
    stats.gpuFrameMs[std::size_t(stats.next)] = float(frame.gpuFrameMs);
    for (StatsState::PassHistory& h : stats.passes) h.ms[std::size_t(stats.next)] = 0.0f;
    for (PassTiming const& p : frame.passes) {
        auto it = std::find_if(stats.passes.begin(), stats.passes.end(),
                               [&](StatsState::PassHistory const& h) { return h.name == p.name; });
        if (it == stats.passes.end()) it = stats.passes.insert(stats.passes.end(), StatsState::PassHistory{p.name, {}});
        it->ms[std::size_t(stats.next)] += float(p.gpuMs);
    }
    stats.next = (stats.next + 1) % StatsState::kHistory;
    stats.count = std::min(stats.count + 1, StatsState::kHistory);
    stats.last = frame;
    stats.cost = cost;
    // About a second of smoothing at 60 Hz; the first sample seeds the average.
    double const k = stats.count == 1 ? 1.0 : 0.05;
    auto blend = [k](double& avg, double v) { avg += (v - avg) * k; };
    blend(stats.costAverage.uiCpuMs, cost.uiCpuMs);
    blend(stats.costAverage.viewersGpuMs, cost.viewersGpuMs);
    blend(stats.costAverage.imguiGpuMs, cost.imguiGpuMs);
    blend(stats.costAverage.frameCpuMs, cost.frameCpuMs);
}

}  // namespace gbl::ui
