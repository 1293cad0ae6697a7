// Frame history for the Stats window.
#include "model/stats_state.h"

#include <algorithm>

namespace gbl::ui {

void recordFrame(StatsState& stats, FrameStats const& frame, EditorCost const& cost) {
    stats.frameMs[std::size_t(stats.next)] = float(cost.frameCpuMs);
    stats.gpuFrameMs[std::size_t(stats.next)] = float(frame.gpuFrameMs);
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
