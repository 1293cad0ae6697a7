// Runs the built gbuffer-lab binary and captures its exit code and output.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace gbl::test {

struct CommandResult {
    int exitCode = -1;
    std::string output;  // stdout and stderr together
};

// Runs binaryPath() with the arguments (each shell-quoted) and waits for it.
CommandResult runGbufferLab(std::vector<std::string> const& args);

// Runs the command and expects exit code 2 with `expect` in its output (gtest EXPECTs, so every
// case of a table is reported). Returns the result for further checks.
CommandResult expectRefused(std::vector<std::string> const& args, std::string const& expect);

// Parses a JSON file the command wrote (throws nlohmann's exception when it is not JSON).
nlohmann::json readJsonFile(std::string const& path);

// A fresh, empty directory under the system temp directory, unique to this test.
std::string freshTempDir(std::string const& name);

}  // namespace gbl::test
