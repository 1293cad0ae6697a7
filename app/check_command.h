// `gbuffer-lab check MANIFEST`: open another program's G-buffer (docs/import.md) and list what looks wrong.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace gbl {

struct CheckOptions {
    std::string manifest;  // a manifest file or a folder
    bool json = false;
    bool time = false;
};

void addCheckOptions(CLI::App& sub, CheckOptions& options);
// 0: no findings; 1: findings (printed); 2: bad input (one sentence naming the field).
int runCheck(CheckOptions const& options);

}  // namespace gbl
