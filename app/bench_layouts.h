// bench --layouts: the whole bench once per G-buffer layout, each table headed by its bytes a pixel.
#pragma once

#include "bench_command.h"

namespace gbl {

// Runs runBench for each layout of options.layouts (the session's or classic when empty), one
// after the other in this process, so the layouts are measured side by side.
int runBenchLayouts(BenchOptions const& options);

}  // namespace gbl
