// Scene open dialog, recent files, loading progress and load errors.
#include "panels/panel_scene_loading.h"
#include "panels/item_rect.h"

#include "model/browser_files.h"
#include "panels/panel_capture.h"
#include "panels/panel_file_browser.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

namespace gbl::ui {

namespace {

constexpr char const* kErrorTitle = "Scene not loaded";

void requestOpen(SceneLoadingState& state, std::string const& path) {
    state.requests.push_back(path);
}

// The file browser for .gltf/.glb; the chosen file is requested like any other open.
void drawOpenDialog(SceneLoadingState& state) {
    if (auto const path = drawFileBrowser(state.browser)) requestOpen(state, *path);
    if (auto const path = drawFileBrowser(state.gbuffer.browser)) state.gbuffer.requests.push_back(*path);
}

void drawProgressWindow(SceneLoadingState& state) {
    if (!state.job) return;
    ImGuiViewport const* vp = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + vp->WorkSize.x * 0.5f, vp->WorkPos.y + 48.0f), ImGuiCond_Always,
                            ImVec2(0.5f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.92f);
    ImGuiWindowFlags const flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
    if (ImGui::Begin("Loading scene", nullptr, flags)) {
        std::string const name = std::filesystem::path(state.job->path).filename().string();
        double const seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - state.job->started).count();
        bool const cancelling = state.job->progress->cancel.load();
        ImGui::Text("Loading %s  (%.1f s)", name.c_str(), seconds);
        std::string stage = currentLoadStage(state);
        if (stage.empty()) stage = "starting";
        if (cancelling)
            stage = "cancelling after " + stage;
        else if (loadHeld(state))
            stage += " (held by a test)";
        ImGui::ProgressBar(currentLoadFraction(state), ImVec2(360.0f, 0.0f), stage.c_str());
        ImGui::SameLine();
        ImGui::BeginDisabled(cancelling);
        if (ImGui::Button("Cancel")) cancelSceneLoad(state);
        ImGui::EndDisabled();
        ImGui::TextDisabled("the current scene stays until the new one is ready");
    }
    ImGui::End();
}

void drawErrorDialog(SceneLoadingState& state) {
    if (state.errorDialogRequested) {
        ImGui::OpenPopup(kErrorTitle);
        state.errorDialogRequested = false;
    }
    if (ImGui::BeginPopupModal(kErrorTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 36.0f);
        ImGui::TextUnformatted(state.lastError.c_str());
        ImGui::PopTextWrapPos();
        ImGui::TextDisabled("The previous scene is still shown. Details are in the Log window.");
        if (ImGui::Button("OK") || state.errorDialogDismissed) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
    state.errorDialogDismissed = false;
}

}  // namespace

void openSceneDialog(SceneLoadingState& state, std::string const& prefill) {
    if (pickFilesInBrowser()) return;  // the browser's own picker; its files arrive as a drop
    openFileBrowser(state.browser, FileBrowserPurpose::OpenScene, prefill);
    // The recent scenes' folders are the first recent places.
    for (auto it = state.recent.rbegin(); it != state.recent.rend(); ++it)
        rememberPlace(state.browser.recentPlaces, std::filesystem::path(*it).parent_path().string());
}

void drawSceneMenuItems(SceneLoadingState& state) {
    if (ImGui::MenuItem("Open scene...", "Ctrl+Shift+O"))
        openSceneDialog(state, state.recent.empty() ? std::string() : state.recent.front());
    state.openItemRect = lastItemRect();
    // The browser's picker hands files over side by side; a glTF whose buffers and textures sit in
    // subfolders opens from its folder, which the page writes into its file system whole.
    if (kInBrowser) {
        if (ImGui::MenuItem("Open folder...")) pickFolderInBrowser();
        state.openFolderItemRect = lastItemRect();
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "A glTF with its buffers and textures in subfolders: choose the folder that holds them all\n"
                "(or drop the folder on the page). The first .gltf or .glb in it by path opens.\n"
                "A G-buffer's folder (manifest.json and its EXR/PNG files, or a render --out folder) opens as\n"
                "File > Open G-buffer does.");
    }
    if (ImGui::BeginMenu("Open recent scene", !state.recent.empty())) {
        for (auto const& r : state.recent)
            if (ImGui::MenuItem(r.c_str())) requestOpen(state, r);
        ImGui::EndMenu();
    }
    if (state.job && ImGui::MenuItem("Cancel scene loading")) cancelSceneLoad(state);
    ImGui::Separator();
    GBufferOpenState& gbuffer = state.gbuffer;
    if (ImGui::MenuItem("Open G-buffer...")) openGBufferDialog(gbuffer);
    gbuffer.menuItemRect = lastItemRect();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Another program's G-buffer: a manifest (docs/import.md) or a folder holding one,\n"
            "or a `gbuffer-lab render --out` folder. It is re-lit live with its own lights.");
    drawCaptureMenuItem(state.capture);
    if (ImGui::MenuItem("Close G-buffer", nullptr, false, gbufferOpen(gbuffer))) gbuffer.closeRequested = true;
}

void openGBufferDialog(GBufferOpenState& state) {
    openFileBrowser(state.browser, FileBrowserPurpose::OpenGBuffer, state.path);
}

void drawSceneLoadingUi(SceneLoadingState& state) {
    drawOpenDialog(state);
    drawProgressWindow(state);
    drawErrorDialog(state);
    // The executable that runs the editor runs `capture` too, wherever it was started from.
    drawCaptureDialog(state.capture, "/proc/self/exe");
}

}  // namespace gbl::ui
