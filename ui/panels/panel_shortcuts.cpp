// Shortcuts window, generated from kShortcuts so it can never list a key that does something else.
#include "panels/panel_shortcuts.h"

#include "model/input_events.h"
#include "panels/gui_util.h"

#include <imgui.h>

namespace gbl::ui {

void drawShortcutsWindow(bool& open) {
    if (!open) return;
    ImGuiIO const& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Appearing,
                            ImVec2(0.5f, 0.5f));
    if (ImGui::Begin("Shortcuts", &open,
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoDocking)) {
        if (ImGui::BeginTable("shortcuts", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
            ImGui::TableSetupColumn("key", ImGuiTableColumnFlags_WidthFixed);
            ImGui::TableSetupColumn("where", ImGuiTableColumnFlags_WidthFixed);
            ImGui::TableSetupColumn("does", ImGuiTableColumnFlags_WidthFixed);
            ImGui::TableHeadersRow();
            for (Shortcut const& s : kShortcuts) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(s.keys.data(), s.keys.data() + s.keys.size());
                ImGui::TableNextColumn();
                ImGui::TextDisabled("%s",
                                    s.scope == ShortcutScope::Viewport ? "over the viewport" : "not while typing");
                ImGui::TableNextColumn();
                std::string const help = shortcutHelp(s);
                ImGui::TextUnformatted(help.c_str());
            }
            ImGui::EndTable();
        }
        ImGui::Separator();
        ImGui::TextDisabled(
            "Mouse over the viewport: left drag orbits, right drag looks, middle drag pans, wheel dollies;");
        ImGui::TextDisabled(
            "a click on a light cube selects it. Number fields: drag, or Ctrl+click / double-click to type.");
    }
    ImGui::End();
}

}  // namespace gbl::ui
