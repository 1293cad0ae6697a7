// Log window.
#include "panels/panel_log.h"

#include "panels/layout.h"
#include "panels/wrapped_text.h"

#include <imgui.h>

#include <cstdio>

namespace gbl::ui {

void drawLogPanel(LogState& log) {
    if (ImGui::Begin(windowName(EditorWindow::Log), nullptr)) {
        if (ImGui::SmallButton("Clear")) {
            log.lines.clear();
            log.errorCount = 0;
        }
        ImGui::BeginChild("log-lines");  // no separator: the short default window keeps a line more
        for (auto const& line : log.lines) wrappedText("%s", line.c_str());
        if (log.scrollToBottom) ImGui::SetScrollHereY(1.0f);
        log.scrollToBottom = false;
        ImGui::EndChild();
    }
    ImGui::End();
}

}  // namespace gbl::ui
