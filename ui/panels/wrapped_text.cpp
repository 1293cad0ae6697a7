// Line breaking at spaces for wrapped text.
#include "panels/wrapped_text.h"

#include <imgui.h>

#include <cstdarg>
#include <cstdio>
#include <string>

namespace gbl::ui {

namespace {
void line(std::string const& text) {
    ImGui::PushTextWrapPos(0.0f);  // breaks only a word wider than the line
    ImGui::TextUnformatted(text.c_str(), text.c_str() + text.size());
    ImGui::PopTextWrapPos();
}
}  // namespace

void wrappedTextUnformatted(std::string_view text) {
    float const width = ImGui::GetContentRegionAvail().x;
    while (true) {
        std::size_t const end = text.find('\n');
        std::string_view paragraph = text.substr(0, end);
        std::string current;
        bool first = true;
        while (true) {
            std::size_t const space = paragraph.find(' ');
            std::string_view const word = paragraph.substr(0, space);
            std::string candidate = first ? std::string(word) : current + " " + std::string(word);
            if (!first && !current.empty() && ImGui::CalcTextSize(candidate.c_str()).x > width) {
                line(current);
                candidate = std::string(word);
            }
            current = std::move(candidate);
            first = false;
            if (space == std::string_view::npos) break;
            paragraph.remove_prefix(space + 1);
        }
        line(current);
        if (end == std::string_view::npos) break;
        text.remove_prefix(end + 1);
    }
}

void wrappedText(char const* fmt, ...) {
    char buffer[2048];
    va_list args;
    va_start(args, fmt);
    std::vsnprintf(buffer, sizeof buffer, fmt, args);
    va_end(args);
    wrappedTextUnformatted(buffer);
}

}  // namespace gbl::ui
