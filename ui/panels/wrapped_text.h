// Wrapped text that breaks lines at spaces only: ImGui's TextWrapped also breaks after '.' and
// ',', which splits numbers ("0." on one line, "9877" on the next).
#pragma once

#include <string_view>

namespace gbl::ui {

// Like ImGui::TextWrapped (printf format, wraps at the window's or the column's edge), breaking
// at spaces; a word wider than the whole line is broken by ImGui as a last resort.
void wrappedText(char const* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
void wrappedTextUnformatted(std::string_view text);

}  // namespace gbl::ui
