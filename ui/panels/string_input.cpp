// The std::string resize callback for ImGui's text fields.
#include "panels/string_input.h"

#include <string>

namespace gbl::ui {

int stringResizeCallback(ImGuiInputTextCallbackData* data) {
    if (data->EventFlag == ImGuiInputTextFlags_CallbackResize) {
        auto* s = static_cast<std::string*>(data->UserData);
        s->resize(std::size_t(data->BufTextLen));
        data->Buf = s->data();
    }
    return 0;
}

}  // namespace gbl::ui
