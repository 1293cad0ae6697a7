// Discard-confirmation modal.
#include "panels/panel_confirm.h"

#include "panels/gui_util.h"

#include <imgui.h>

namespace gbl::ui {

void drawDiscardConfirmation(DiscardGuard& guard) {
    if (!guard.asking) return;
    char const* title = "Unsaved edits";
    if (!ImGui::IsPopupOpen(title)) ImGui::OpenPopup(title);
    if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::Text("%s? The edits since the session was last saved will be lost.", discardingVerb(*guard.asking));
    ImGui::TextDisabled("Cancel, then File > Save session (Ctrl+S) to keep them.");
    float const w = ImGui::GetFontSize() * 7.0f;
    if (ImGui::Button("Discard", ImVec2(w, 0))) {
        guard.confirmed = guard.asking;
        guard.asking.reset();
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(w, 0)) || escapePressed()) {
        guard.asking.reset();
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

}  // namespace gbl::ui
