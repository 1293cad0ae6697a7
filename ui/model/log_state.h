// The editor log: lines, error count, and the function every layer uses to add to it.
#pragma once

#include <string>
#include <vector>

namespace gbl::ui {

struct LogState {
    std::vector<std::string> lines;
    bool scrollToBottom = false;
    int errorCount = 0;  // lines that reported a failure, shown as a badge in the menu bar
};

// Keeps the last few hundred lines; older ones are dropped so a long session stays small.
void logMessage(LogState& log, std::string line, bool isError = false);

}  // namespace gbl::ui
