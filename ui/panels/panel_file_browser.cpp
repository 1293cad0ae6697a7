// File browser modal: folder bar with Up and recent places, a list of folders and matching
// files, a name field and OK/Cancel.
#include "panels/panel_file_browser.h"

#include "panels/gui_util.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace gbl::ui {

namespace {

std::string sizeText(std::uintmax_t bytes) {
    char text[32];
    if (bytes >= 1024u * 1024u)
        std::snprintf(text, sizeof text, "%.1f MB", double(bytes) / (1024.0 * 1024.0));
    else
        std::snprintf(text, sizeof text, "%.1f kB", double(bytes) / 1024.0);
    return text;
}

// The recent places and the folder bar; navigation errors land in state.error.
void drawFolderBar(FileBrowserState& state) {
    ImGui::BeginDisabled(state.folder == "/");
    if (ImGui::Button("Up")) goToParent(state);
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Refresh")) refreshFolder(state);
    ImGui::SameLine();
    ImGui::BeginDisabled(state.recentPlaces.empty());
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 10.0f);
    if (ImGui::BeginCombo("##recent", "Recent places")) {
        for (std::string const& place : state.recentPlaces)
            if (ImGui::Selectable(place.c_str())) changeFolder(state, place);
        ImGui::EndCombo();
    }
    ImGui::EndDisabled();
    // The folder as one absolute path; long ones wrap rather than run off the window.
    ImGui::TextDisabled("Folder");
    ImGui::SameLine();
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(state.folder.c_str());
    ImGui::PopTextWrapPos();
}

// Returns true when a file was double-clicked (confirm).
bool drawEntries(FileBrowserState& state, float height) {
    bool confirm = false;
    std::string enter;
    beginFramedChild("entries", ImVec2(0, height));
    float const sizeColumn = ImGui::CalcTextSize("0000.0 MB").x;
    for (std::size_t i = 0; i < state.entries.size(); ++i) {
        FileEntry const& e = state.entries[i];
        ImGui::PushID(int(i));
        std::string const label = e.folder ? e.name + "/" : e.name;
        bool const selected = state.selected == int(i);
        if (ImGui::Selectable(label.c_str(), selected, ImGuiSelectableFlags_AllowDoubleClick)) {
            state.selected = int(i);
            if (!e.folder) state.fileName = e.name;
            if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
                if (e.folder)
                    enter = e.name;
                else
                    confirm = true;
            }
        }
        if (!e.folder) {
            std::string const size = sizeText(e.bytes);
            ImGui::SameLine(std::max(ImGui::GetContentRegionAvail().x, sizeColumn) -
                            ImGui::CalcTextSize(size.c_str()).x);
            ImGui::TextDisabled("%s", size.c_str());
        }
        ImGui::PopID();
    }
    if (state.entries.empty()) ImGui::TextDisabled("no folders or matching files here");
    ImGui::EndChild();
    if (!enter.empty()) enterFolder(state, enter);
    return confirm;
}

}  // namespace

std::optional<std::string> drawFileBrowser(FileBrowserState& state) {
    if (!state.open) return std::nullopt;
    char const* title = browserTitle(state.purpose);
    if (state.justOpened) ImGui::OpenPopup(title);
    // Sized from the font and the window: about 70 characters wide, never past the display.
    ImVec2 const display = ImGui::GetIO().DisplaySize;
    float const em = ImGui::GetFontSize();
    ImGui::SetNextWindowSize(ImVec2(std::min(em * 44.0f, display.x * 0.9f), std::min(em * 30.0f, display.y * 0.85f)),
                             ImGuiCond_Appearing);
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    std::optional<std::string> chosen;
    bool keepOpen = true;
    if (!ImGui::BeginPopupModal(title, &keepOpen)) {
        if (!state.justOpened) state.open = false;  // closed by its title bar button
        state.justOpened = false;
        return std::nullopt;
    }
    drawFolderBar(state);
    std::string extensions;
    for (std::string const& e : state.extensions) extensions += (extensions.empty() ? "" : " ") + e;
    float const footer = ImGui::GetFrameHeightWithSpacing() * 2.0f + ImGui::GetTextLineHeightWithSpacing() * 2.0f;
    bool confirm = drawEntries(state, std::max(ImGui::GetContentRegionAvail().y - footer, em * 4.0f));

    char name[1024];
    std::snprintf(name, sizeof name, "%s", state.fileName.c_str());
    if (state.justOpened) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(-ImGui::GetFontSize() * 6.0f);
    if (ImGui::InputText("Name", name, sizeof name, ImGuiInputTextFlags_EnterReturnsTrue)) confirm = true;
    state.fileName = name;
    ImGui::TextDisabled("shows folders and %s files", extensions.empty() ? "all" : extensions.c_str());
    if (state.purpose == FileBrowserPurpose::OpenGBuffer)
        ImGui::TextDisabled("Open with no name opens the folder shown (a render --out folder)");
    if (!state.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.35f, 1.0f));
        ImGui::TextWrapped("%s", state.error.c_str());
        ImGui::PopStyleColor();
    }
    char const* ok = state.purpose == FileBrowserPurpose::SaveSession ? "Save" : "Open";
    if (ImGui::Button(ok, ImVec2(em * 6.0f, 0))) confirm = true;
    ImGui::SameLine();
    bool const cancel = ImGui::Button("Cancel", ImVec2(em * 6.0f, 0)) || escapePressed();
    if (confirm) chosen = confirmFileBrowser(state);
    if (chosen || cancel || !keepOpen) {
        state.open = false;
        ImGui::CloseCurrentPopup();
    }
    state.justOpened = false;
    ImGui::EndPopup();
    return chosen;
}

}  // namespace gbl::ui
