// The viewport toolbar's Checks button and its list (viewport_checks.h).
#include "panels/viewport_checks.h"
#include "panels/item_rect.h"

#include <imgui.h>

#include <cstdio>
#include <string>

namespace gbl::ui {

void drawChecksButton(ViewportState& state) {
    state.checksRect = glm::vec4(0.0f);
    state.firstFindingRect = glm::vec4(0.0f);
    state.precisionShown = 0;
    if (state.importedFrame.empty()) return;
    std::size_t const n = state.findings.size();
    std::string const label = n == 0 ? "Checks: none" : "Checks: " + std::to_string(n);
    if (n > 0) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.62f, 0.22f, 0.45f, 1.0f));
    if (ImGui::Button(label.c_str())) ImGui::OpenPopup("gbuffer-checks");
    if (n > 0) ImGui::PopStyleColor();
    state.checksRect = lastItemRect();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "what `gbuffer-lab check` finds in this G-buffer: click for the list, and a finding to\n"
            "mark its pixels over the image");
    ImGui::SameLine();
    if (!ImGui::BeginPopup("gbuffer-checks")) return;
    if (n == 0) ImGui::TextUnformatted("No finding: every check passed (docs/import.md, \"Checks\").");
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 32.0f);
    for (std::size_t i = 0; i < n; ++i) {
        GBufferFinding const& f = state.findings[i];
        char head[192];
        std::snprintf(head, sizeof head, "%s%s (%s): %zu px, %.3g %% of the frame", f.check.c_str(),
                      f.heuristic ? " [heuristic]" : "", f.attachment.c_str(), f.pixels, 100.0 * f.share);
        bool const marked = state.markedFinding == int(i);
        ImGui::PushID(int(i));
        if (ImGui::RadioButton(head, marked)) state.markedFinding = marked ? -1 : int(i);
        if (i == 0) state.firstFindingRect = lastItemRect();
        ImGui::PopID();
        ImGui::Indent();
        ImGui::TextWrapped("%s", f.cause.c_str());
        ImGui::Unindent();
    }
    if (state.markedFinding >= 0 && ImGui::Button("Unmark")) state.markedFinding = -1;
    // What the storage can hold, finding or not: the answer to "is 8 bits enough for my normals?".
    if (!state.precision.empty()) {
        ImGui::Separator();
        ImGui::TextUnformatted("Precision: what each attachment's storage can hold");
        for (std::string const& line : state.precision) ImGui::BulletText("%s", line.c_str());
        state.precisionShown = int(state.precision.size());
    }
    ImGui::PopTextWrapPos();
    ImGui::EndPopup();
}

}  // namespace gbl::ui
