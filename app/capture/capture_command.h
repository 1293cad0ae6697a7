// `gbuffer-lab capture [--frame N] [--out DIR] [--open] -- PROGRAM [ARGS...]` and `capture --trace FILE`:
// a frame of another OpenGL program, recorded by apitrace, turned into a G-buffer manifest.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace gbl {

struct CaptureOptions {
    std::vector<std::string> program;  // PROGRAM [ARGS...] after --
    std::string trace;                 // an existing trace instead
    int frame = 1;
    std::string outDir = "capture";
    std::string api = "auto";
    double timeout = 60.0;
    bool open = false;
    bool time = false;
};

void addCaptureOptions(CLI::App& sub, CaptureOptions& options);
// 0: a manifest was written; 2: one sentence saying why not.
int runCapture(CaptureOptions const& options, char const* self);

}  // namespace gbl
