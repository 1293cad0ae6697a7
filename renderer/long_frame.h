// The warning before a frame that would take a long time (core/frame_cost.h's estimate), and the
// mode that gives the same image sooner. `render` prints it; the editor switches mode with it.
#pragma once

#include "core/frame_cost.h"
#include "renderer.h"

#include <optional>
#include <string>

namespace gbl {

struct LongFrameWarning {
    std::string message;                       // one sentence: the estimate, and the cheaper mode if any
    FrameCostEstimate estimate;                // the frame as asked
    std::optional<FrameCostEstimate> cheaper;  // the cheapest mode available on this context, if cheaper
};

// Seconds per light-pixel pair assumed on this renderer's context before anything is measured.
double assumedSecondsPerPair(GlCaps const& caps);

// nullopt when `input` at the renderer's size is estimated at `thresholdSeconds` or less;
// otherwise the warning. Asks modeUnavailable() of the other modes only then (it builds them).
std::optional<LongFrameWarning> longFrameWarning(Renderer& renderer, FrameInput const& input, double thresholdSeconds);

}  // namespace gbl
