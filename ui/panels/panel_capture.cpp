// File > Capture a program… and its dialog (issue 49): the command line, the frame, the folder, what
// the program draws through; while `capture` runs, its progress and Cancel; a refusal in one sentence.
#include "panels/panel_capture.h"

#include "model/browser_files.h"
#include "panels/item_rect.h"
#include "panels/string_input.h"
#include "panels/wrapped_text.h"

#include <imgui.h>

#include <chrono>
#include <filesystem>

namespace gbl::ui {

namespace {

constexpr char const* kTitle = "Capture a program";

void stringField(char const* label, std::string& text, bool disabled) {
    ImGui::BeginDisabled(disabled);
    ImGui::SetNextItemWidth(-1.0f);
    ImGui::InputText(label, text.data(), text.capacity() + 1, ImGuiInputTextFlags_CallbackResize, stringResizeCallback,
                     &text);
    ImGui::EndDisabled();
}

}  // namespace

void openCaptureDialog(ProgramCaptureState& state) {
    state.dialogOpen = true;
    state.focusCommand = true;
    if (state.outDir.empty()) {
        std::error_code ec;
        state.outDir = (std::filesystem::current_path(ec) / "capture").string();
    }
}

void drawCaptureMenuItem(ProgramCaptureState& state) {
    state.menuItemRect = glm::vec4(0.0f);
    if (kInBrowser) return;  // a page runs no programs
    if (ImGui::MenuItem("Capture a program...")) openCaptureDialog(state);
    state.menuItemRect = lastItemRect();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Runs another OpenGL program under apitrace until the frame you name, finds its G-buffer\n"
            "and lighting passes, and opens what it stored there (gbuffer-lab capture).");
}

void drawCaptureDialog(ProgramCaptureState& state, std::string const& self) {
    state.commandRect = state.frameRect = state.outRect = state.eglRect = state.captureButtonRect = glm::vec4(0.0f);
    if (!state.dialogOpen) return;
    ImGuiViewport const* vp = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + vp->WorkSize.x * 0.5f, vp->WorkPos.y + vp->WorkSize.y * 0.3f),
                            ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    // A fixed width, the height fitted every frame: the progress line and a refusal's sentence come and go.
    ImGui::SetNextWindowSize(ImVec2(ImGui::GetFontSize() * 34.0f, 0.0f), ImGuiCond_Always);
    bool open = true;
    if (!ImGui::Begin(kTitle, &open, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoDocking)) {
        ImGui::End();
        state.dialogOpen = open;
        return;
    }
    bool const running = captureRunning(state);
    ImGui::TextUnformatted("Command line (the program and its arguments):");
    if (state.focusCommand) {
        ImGui::SetKeyboardFocusHere();
        state.focusCommand = false;
    }
    stringField("##command", state.commandLine, running);
    state.commandRect = lastItemRect();
    ImGui::BeginDisabled(running);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    ImGui::InputInt("Frame (from 0)", &state.frame);
    state.frameRect = lastItemRect();
    if (state.frame < 0) state.frame = 0;
    ImGui::TextUnformatted("Draws through:");
    ImGui::SameLine();
    if (ImGui::RadioButton("auto", state.api == CaptureApi::Auto)) state.api = CaptureApi::Auto;
    ImGui::SameLine();
    if (ImGui::RadioButton("EGL", state.api == CaptureApi::Egl)) state.api = CaptureApi::Egl;
    state.eglRect = lastItemRect();
    ImGui::SameLine();
    if (ImGui::RadioButton("GLX", state.api == CaptureApi::Glx)) state.api = CaptureApi::Glx;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("auto: EGL when there is no X display, else GLX");
    ImGui::EndDisabled();
    ImGui::TextUnformatted("Folder for the manifest and images:");
    stringField("##out", state.outDir, running);
    state.outRect = lastItemRect();
    ImGui::Separator();
    if (running) {
        CaptureJob const& job = *state.job;
        double const seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - job.started).count();
        ImGui::Text("Capturing frame %d of %s  (%.1f s)", job.frame, job.program.c_str(), seconds);
        // No fraction is known before the frame is reached: the bar moves to show the editor waits.
        ImGui::ProgressBar(-1.0f * float(ImGui::GetTime()), ImVec2(-1.0f, 0.0f), "capturing...");
        if (ImGui::Button("Cancel")) cancelProgramCapture(state);
    } else {
        if (ImGui::Button("Capture and open")) startProgramCapture(state, self);
        state.captureButtonRect = lastItemRect();
        ImGui::SameLine();
        if (ImGui::Button("Close")) open = false;
    }
    if (!state.lastError.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        wrappedTextUnformatted(state.lastError);
        ImGui::PopStyleColor();
    }
    ImGui::End();
    state.dialogOpen = open;
}

}  // namespace gbl::ui
