// Sessions inside the editor.
#include "editor_session.h"

#include "camera_rig.h"
#include "imgui_compat.h"

#include <imgui.h>

#include <cstdio>

namespace gbl::ui {

Session sessionFromEditor(EditorState const& state, int defaultSceneLights) {
    Session s;
    s.scene = state.sceneSource.empty() ? std::string("default") : state.sceneSource;
    s.defaultSceneLights = defaultSceneLights;
    s.camera = state.camera;
    s.lights = state.lights;
    s.pipeline = state.pipeline;
    s.viewers = state.gbuffer.viewers;
    s.animation = state.animation;
    return s;
}

void applySessionValues(Session const& session, EditorState& state) {
    state.camera = session.camera;
    resetTargetAhead(state.rig, state.camera, glm::length(state.camera.position - state.sceneBounds.center()));
    state.lights = session.lights;
    state.pipeline = session.pipeline;
    state.gbuffer.viewers = session.viewers;
    state.animation = session.animation;
    state.lightsPanel.selected = state.lights.empty() ? -1 : 0;
    state.lightsPanel.message.clear();
}

namespace {
constexpr char const* kOpenPopup = "Open session";
constexpr char const* kSavePopup = "Save session";
constexpr char const* kRecoveryPopup = "Recover unsaved work";

// One popup for both directions: a path field and a confirm button.
void pathPopup(char const* name, SessionUiState& ui, char const* action, std::optional<std::string>& result) {
    if (!ImGui::BeginPopupModal(name, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::TextUnformatted("Session file (JSON):");
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 30.0f);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    bool const entered = ImGui::InputText("##path", ui.pathInput, sizeof ui.pathInput, ImGuiInputTextFlags_EnterReturnsTrue);
    if (!ui.message.empty()) ImGui::TextWrapped("%s", ui.message.c_str());
    if (ImGui::Button(action) || entered) {
        result = std::string(ui.pathInput);
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}
}  // namespace

void drawSessionPopups(SessionUiState& ui) {
    ui.openPath.reset();
    ui.savePath.reset();
    if (ui.openRequested) ImGui::OpenPopup(kOpenPopup);
    if (ui.saveRequested) ImGui::OpenPopup(kSavePopup);
    ui.openRequested = ui.saveRequested = false;
    pathPopup(kOpenPopup, ui, "Open", ui.openPath);
    pathPopup(kSavePopup, ui, "Save", ui.savePath);

    // Not modal: the editor stays usable (and testable) while the offer is open.
    if (ui.recoveryOffer) {
        ImGuiViewport const* vp = ImGui::GetMainViewport();
        ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + vp->WorkSize.x * 0.5f, vp->WorkPos.y + vp->WorkSize.y * 0.3f),
                                ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
        if (!ui.recoveryShown) ImGui::SetNextWindowFocus();  // once, so it does not steal focus every frame
        ui.recoveryShown = true;
        if (ImGui::Begin(kRecoveryPopup, nullptr,
                         ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse | kNoDockingFlag)) {
            ImGui::Text("A previous editor (process %ld) ended without closing cleanly.", ui.recoveryOffer->pid);
            ImGui::Text("Its autosaved session: %s", ui.recoveryOffer->sessionPath.c_str());
            if (ImGui::Button("Restore it")) ui.acceptRecovery = true;
            ImGui::SameLine();
            if (ImGui::Button("Discard it")) ui.declineRecovery = true;
        }
        ImGui::End();
    }
}

}  // namespace gbl::ui
