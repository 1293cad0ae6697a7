// `gbuffer-lab compare A.json B.json`: two session files rendered headlessly and their lit frames diffed.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace gbl {

struct CompareOptions {
    std::string sessionA;
    std::string sessionB;
    std::string outDir;
    std::string size = "1280x720";
    // Pixels whose largest RGB difference of the lit HDR frames exceeds this count as differing:
    // 2e-3 is the fp16 bound the GL tests use (2^-11 relative storage plus GPU pow()).
    float threshold = 2e-3f;
    bool allowOutsideUris = false;
};

void addCompareOptions(CLI::App& sub, CompareOptions& options);
// 0 on success, 2 for bad arguments or sessions that cannot be compared (different scenes), 1
// when no GL context can be had.
int runCompare(CompareOptions const& options);

}  // namespace gbl
