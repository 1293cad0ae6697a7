// The editor log.
#include "model/log_state.h"

#include <cstdio>

namespace gbl::ui {

namespace {
constexpr std::size_t kMaxLogLines = 500;
}

void logMessage(LogState& log, std::string line, bool isError) {
    // Also on stderr: a teacher who starts the editor from a terminal sees shader errors there.
    std::fprintf(stderr, "gbuffer-lab: %s\n", line.c_str());
    if (isError) ++log.errorCount;
    log.lines.push_back(std::move(line));
    if (log.lines.size() > kMaxLogLines) log.lines.erase(log.lines.begin(), log.lines.begin() + 100);
    log.scrollToBottom = true;
}

}  // namespace gbl::ui
