// Glossary window.
#include "panels/panel_glossary.h"

#include "panels/string_input.h"
#include "panels/wrapped_text.h"

#include <imgui.h>

#include <algorithm>
#include <cctype>

namespace gbl::ui {

namespace {

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

}  // namespace

void glossaryTooltip(GlossaryTerm const& term) {
    if (!ImGui::IsItemHovered()) return;
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
    ImGui::TextUnformatted(term.term.c_str());
    ImGui::Separator();
    ImGui::TextUnformatted(term.definition.c_str());
    ImGui::TextDisabled("click: open the glossary here");
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

void drawGlossaryWindow(GlossaryWindowState& state, Glossary const& glossary) {
    if (!state.open) return;
    ImGuiViewport const* vp = ImGui::GetMainViewport();
    ImGui::SetNextWindowSize(ImVec2(std::min(520.0f, vp->WorkSize.x * 0.6f), std::min(520.0f, vp->WorkSize.y * 0.8f)),
                             ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + vp->WorkSize.x * 0.5f, vp->WorkPos.y + vp->WorkSize.y * 0.5f),
                            ImGuiCond_FirstUseEver, ImVec2(0.5f, 0.5f));
    if (!state.focus.empty()) ImGui::SetNextWindowFocus();
    if (ImGui::Begin("Glossary", &state.open)) {
        if (!glossary.error.empty()) wrappedText("%s", glossary.error.c_str());
        ImGui::SetNextItemWidth(-1.0f);
        ImGui::InputTextWithHint("##filter", "filter", state.filter.data(), state.filter.capacity() + 1,
                                 ImGuiInputTextFlags_CallbackResize, stringResizeCallback, &state.filter);
        std::string const filter = lower(state.filter);
        for (std::size_t i = 0; i < glossary.terms.size(); ++i) {
            GlossaryTerm const& t = glossary.terms[i];
            bool const focused = !state.focus.empty() && lower(state.focus) == lower(t.term);
            if (!filter.empty() && !focused && lower(t.term).find(filter) == std::string::npos &&
                lower(t.definition).find(filter) == std::string::npos)
                continue;
            ImGui::PushID(int(i));
            if (focused) {
                ImGui::SetNextItemOpen(true);
                state.shownTerm = t.term;
            }
            if (ImGui::CollapsingHeader(t.term.c_str())) {
                ImGui::Indent();
                wrappedTextUnformatted(t.definition);
                if (!t.aliases.empty()) {
                    std::string also;
                    for (auto const& a : t.aliases) also += (also.empty() ? "" : ", ") + a;
                    ImGui::TextDisabled("also: %s", also.c_str());
                }
                ImGui::Unindent();
            }
            if (focused) ImGui::SetScrollHereY(0.0f);
            ImGui::PopID();
        }
    }
    ImGui::End();
    state.focus.clear();
}

}  // namespace gbl::ui
