// Frame history and editor cost shown by the Stats window, as plain values.
#pragma once

#include "core/frame_types.h"

#include <array>
#include <string>
#include <vector>

namespace gbl::ui {

// What the editor itself costs per frame, measured around its own work (not the renderer's).
struct EditorCost {
    double uiCpuMs = 0.0;       // building the ImGui frame (all panels)
    double viewersGpuMs = 0.0;  // G-buffer viewer passes (timer query)
    double imguiGpuMs = 0.0;    // drawing the ImGui draw lists (timer query)
    double frameCpuMs = 0.0;    // whole loop iteration, wall clock
};

struct StatsState {
    static constexpr int kHistory = 240;
    std::array<float, kHistory> frameMs{};     // wall-clock time between frames
    std::array<float, kHistory> gpuFrameMs{};  // renderer passes, summed
    // Each pass seen so far, in the order first seen, with its time in the same ring as frameMs
    // (0 in a frame where it did not run).
    struct PassHistory {
        std::string name;
        std::array<float, kHistory> ms{};
    };
    std::vector<PassHistory> passes;
    int next = 0;
    int count = 0;
    FrameStats last;
    EditorCost cost;
    EditorCost costAverage;  // exponential average, for a readable number
};

void recordFrame(StatsState& stats, FrameStats const& frame, EditorCost const& cost);

}  // namespace gbl::ui
