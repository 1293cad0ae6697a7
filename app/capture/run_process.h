// Child processes for the capture: apitrace and the retracer, run without a shell.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace gbl::capture {

// The full path of `name` on PATH (or `name` itself when it holds a slash and is executable).
std::optional<std::string> findProgram(std::string const& name);

struct ProcessResult {
    bool started = false;
    int exitCode = -1;  // -1 when it ended by a signal
    int signal = 0;     // the signal that ended it, if any
    bool stoppedByUs = false;
    std::string error;  // why it did not start
};

struct ProcessOptions {
    std::string stdoutPath;                                // empty: inherit
    std::string stderrPath;                                // empty: inherit
    std::vector<std::pair<std::string, std::string>> env;  // set in the child
    // Asked every 0.2 s while the child runs: true stops it (SIGTERM to its process group, so the
    // traced program ends with apitrace and the trace is flushed).
    std::function<bool()> shouldStop;
    double timeoutSeconds = 0.0;  // 0: none; past it the child is stopped as above
};

ProcessResult runProcess(std::vector<std::string> const& argv, ProcessOptions const& options);

// Runs and returns stdout as a string (stderr to `stderrPath` when given, else discarded).
std::optional<std::string> runForOutput(std::vector<std::string> const& argv, std::string* error,
                                        std::vector<std::pair<std::string, std::string>> const& env = {});

}  // namespace gbl::capture
