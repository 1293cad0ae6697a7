// Session, export and recovery dialogs: a path field per action, a modal for the recovery offer.
#include "panels/panel_session.h"
#include "panels/item_rect.h"

#include "model/browser_files.h"
#include "panels/panel_file_browser.h"
#include "panels/panel_gbuffer.h"

#include <imgui.h>

#include <algorithm>
#include <cstring>
#include <utility>

namespace gbl::ui {

namespace {

char const* dialogTitle(SessionDialog d) {
    switch (d) {
        case SessionDialog::Open:
            return "Open session";
        case SessionDialog::Save:
            return "Save session as";
        case SessionDialog::ExportAll:
            return "Export all";
        case SessionDialog::ExportViewer:
            return "Export viewer";
        case SessionDialog::None:
            break;
    }
    return "";
}

char const* pathLabel(SessionDialog d) {
    return d == SessionDialog::ExportAll ? "Folder" : "File";
}

}  // namespace

void openSessionDialog(SessionPanelState& state, SessionDialog dialog, std::string const& prefill) {
    // In the browser its own picker chooses the file, which arrives as a drop (editor_frame.cpp).
    if (dialog == SessionDialog::Open && pickFilesInBrowser()) return;
    if (dialog == SessionDialog::Open || dialog == SessionDialog::Save) {
        state.message.clear();
        openFileBrowser(
            state.browser,
            dialog == SessionDialog::Open ? FileBrowserPurpose::OpenSession : FileBrowserPurpose::SaveSession, prefill);
        return;
    }
    state.dialog = dialog;
    state.dialogJustOpened = true;
    state.message.clear();
    state.pathInput.fill('\0');
    std::memcpy(state.pathInput.data(), prefill.data(), std::min(prefill.size(), state.pathInput.size() - 1));
}

void drawSessionMenuItems(SessionPanelState& state) {
    std::string const current = state.currentPath.empty() ? "session.json" : state.currentPath;
    if (ImGui::MenuItem("Open session...", "Ctrl+O")) openSessionDialog(state, SessionDialog::Open, current);
    if (ImGui::MenuItem("Save session", "Ctrl+S")) {
        if (state.currentPath.empty())
            openSessionDialog(state, SessionDialog::Save, current);
        else
            state.saveRequested = true;
    }
    if (ImGui::MenuItem("Save session as...")) openSessionDialog(state, SessionDialog::Save, current);
    ImGui::Separator();
    if (ImGui::MenuItem("Export viewer...")) openSessionDialog(state, SessionDialog::ExportViewer, "");
    if (ImGui::MenuItem("Export all...")) openSessionDialog(state, SessionDialog::ExportAll, "export");
    state.exportAllItemRect = lastItemRect();
}

void finishSessionRequest(SessionPanelState& state, std::optional<std::string> const& error) {
    if (error) {
        state.message = *error;
        return;
    }
    state.message.clear();
    // The modal is closed from inside its own Begin/End on the next frame (ImGui's rule).
    state.closePending = state.dialog != SessionDialog::None;
}

SessionRequest drawSessionDialogs(SessionPanelState& state) {
    SessionRequest request;
    if (state.openDropped) return {SessionRequestKind::Open, *std::exchange(state.openDropped, std::nullopt), 0};
    // "Save session" with a known path needs no dialog: it is handed over directly.
    if (state.saveRequested) {
        state.saveRequested = false;
        if (!state.currentPath.empty()) return {SessionRequestKind::Save, state.currentPath, 0};
        openSessionDialog(state, SessionDialog::Save, "session.json");
    }

    if (state.recoveryOffer) {
        ImGui::OpenPopup("Unsaved changes");
        if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
            ImGui::TextUnformatted(state.recoveryTitle.c_str());
            if (!state.recoveryWhy.empty()) ImGui::TextUnformatted(state.recoveryWhy.c_str());
            if (!state.recoveryCause.empty()) ImGui::TextDisabled("%s", state.recoveryCause.c_str());
            if (ImGui::Button("Restore")) {
                request = {SessionRequestKind::Restore, state.recoveryOffer->sessionPath, 0};
                ImGui::CloseCurrentPopup();
            }
            ImGui::SameLine();
            if (ImGui::Button("Discard")) {
                request = {SessionRequestKind::DiscardRecovery, state.recoveryOffer->sessionPath, 0};
                ImGui::CloseCurrentPopup();
            }
            ImGui::EndPopup();
        }
        return request;
    }

    if (state.browser.open) {
        if (auto const path = drawFileBrowser(state.browser)) {
            bool const saving = state.browser.purpose == FileBrowserPurpose::SaveSession;
            return {saving ? SessionRequestKind::Save : SessionRequestKind::Open, *path, 0};
        }
        return request;
    }
    if (state.dialog == SessionDialog::None) return request;
    char const* title = dialogTitle(state.dialog);
    ImGui::OpenPopup(title);
    bool open = true;
    if (state.closePending) {
        if (ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
            ImGui::CloseCurrentPopup();
            ImGui::EndPopup();
        }
        state.closePending = false;
        state.dialog = SessionDialog::None;
        return request;
    }
    if (ImGui::BeginPopupModal(title, &open, ImGuiWindowFlags_AlwaysAutoResize)) {
        if (state.dialog == SessionDialog::ExportViewer) {
            for (std::size_t i = 0; i < kViewerNames.size(); ++i) {
                if (i) ImGui::SameLine();
                ImGui::RadioButton(kViewerNames[i].data(), &state.exportViewer, int(i));
            }
            ImGui::Checkbox("Raw attachment as float EXR (else the picture as PNG)", &state.exportRaw);
        }
        if (state.dialogJustOpened) ImGui::SetKeyboardFocusHere();
        state.dialogJustOpened = false;
        ImGui::SetNextItemWidth(480.0f);
        bool const entered = ImGui::InputText(pathLabel(state.dialog), state.pathInput.data(), state.pathInput.size(),
                                              ImGuiInputTextFlags_EnterReturnsTrue);
        if (kInBrowser && state.dialog == SessionDialog::ExportAll)
            ImGui::TextDisabled("The browser offers the folder as one download, gbuffer-lab-<folder>.zip.");
        if (!state.message.empty()) ImGui::TextWrapped("%s", state.message.c_str());
        bool const ok = ImGui::Button(state.dialog == SessionDialog::Open ? "Open" : "Save") || entered;
        ImGui::SameLine();
        bool const cancel = ImGui::Button("Cancel");
        std::string const path = state.pathInput.data();
        if (ok && !path.empty()) {
            switch (state.dialog) {
                case SessionDialog::Open:
                    request.kind = SessionRequestKind::Open;
                    break;
                case SessionDialog::Save:
                    request.kind = SessionRequestKind::Save;
                    break;
                case SessionDialog::ExportAll:
                    request.kind = SessionRequestKind::ExportAll;
                    break;
                case SessionDialog::ExportViewer:
                    request.kind =
                        state.exportRaw ? SessionRequestKind::ExportViewerExr : SessionRequestKind::ExportViewerPng;
                    break;
                case SessionDialog::None:
                    break;
            }
            request.path = path;
            request.viewer = state.exportViewer;
        } else if (ok) {
            state.message = "Type a path first.";
        }
        if (cancel) {
            state.dialog = SessionDialog::None;
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }
    if (!open) state.dialog = SessionDialog::None;
    return request;
}

}  // namespace gbl::ui
