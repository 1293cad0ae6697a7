// Typing into a std::string through ImGui: the resize callback that grows the string as text is
// typed, so a field has no fixed length (pass the string as user data with
// ImGuiInputTextFlags_CallbackResize).
#pragma once

#include <imgui.h>

namespace gbl::ui {

int stringResizeCallback(ImGuiInputTextCallbackData* data);

}  // namespace gbl::ui
