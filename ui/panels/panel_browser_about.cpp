// About this browser window: the browser build's limits as one list.
#include "panels/panel_browser_about.h"

#include "panels/gui_util.h"
#include "panels/wrapped_text.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cctype>

namespace gbl::ui {

namespace {
// What every page lacks, whatever the browser: the one place that says it.
constexpr std::array<char const*, 4> kPageLimits{
    "There is no Quit: the editor ends with its tab. The window layout, the lesson progress and unsaved "
    "changes stay in this browser's storage for the next visit.",
    "Ctrl+N stays the browser's (a new window): File > New session starts a new session.",
    "Files live in the page's memory: a saved session, an export or a screenshot is offered as a download.",
    "Scenes and sessions open from your computer through the File menu, or dropped on the page "
    "(a glTF with its folder too).",
};
}  // namespace

std::vector<std::string> browserLimits(BrowserAboutState const& state, std::string const& timingSource) {
    std::vector<std::string> lines;
    for (std::string line : state.contextLimits) {  // the renderer's words, as a sentence
        if (!line.empty()) line[0] = char(std::toupper(static_cast<unsigned char>(line[0])));
        lines.push_back(line + ".");
    }
    if (timingSource == "cpu_finish")
        lines.push_back(
            "This browser offers no GPU timer queries: the Stats window's pass times are "
            "measured on the page's thread and are rough.");
    for (char const* line : kPageLimits) lines.emplace_back(line);
    return lines;
}

void drawBrowserAboutWindow(BrowserAboutState& state, std::span<std::string const> lines) {
    if (!state.open) return;
    ImGuiIO const& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Appearing,
                            ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(640.0f, io.DisplaySize.x * 0.9f), 0.0f), ImGuiCond_Appearing);
    if (ImGui::Begin("About this browser", &state.open, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoDocking)) {
        wrappedText("gbuffer-lab runs here on WebGL2. What it cannot do in this browser:");
        ImGui::Separator();
        for (std::string const& line : lines) {
            ImGui::Bullet();
            ImGui::SameLine();
            wrappedText("%s", line.c_str());
        }
    }
    ImGui::End();
}

}  // namespace gbl::ui
