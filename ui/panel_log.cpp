// Log window.
#include "panel_log.h"

#include "layout.h"

#include <imgui.h>

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

void drawLogPanel(LogState& log) {
    placeWindow(EditorWindow::Log);
    if (ImGui::Begin(windowName(EditorWindow::Log), nullptr, editorWindowFlags())) {
        if (ImGui::SmallButton("Clear")) {
            log.lines.clear();
            log.errorCount = 0;
        }
        ImGui::Separator();
        ImGui::BeginChild("log-lines");
        for (auto const& line : log.lines) ImGui::TextWrapped("%s", line.c_str());
        if (log.scrollToBottom) ImGui::SetScrollHereY(1.0f);
        log.scrollToBottom = false;
        ImGui::EndChild();
    }
    ImGui::End();
}

}  // namespace gbl::ui
