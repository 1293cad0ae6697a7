// The editor's own section of imgui.ini: the UI scale and the scale the saved dock tree was built for.
#include "editor_loop.h"
#include "panels/panel_log.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>

namespace gbl {

namespace {

// The UI scale's entry in imgui.ini, "[gbuffer-lab][View]" with a line "UiScale=1.5": kept with the
// window layout, read before the first frame, written whenever ImGui saves the layout.
void* readViewSettingsOpen(ImGuiContext*, ImGuiSettingsHandler*, char const* name) {
    return std::string_view(name) == "View" ? reinterpret_cast<void*>(1) : nullptr;
}

// "LayoutScale=1.5": the scale the saved dock tree was built for (LayoutState::builtScale); a tree
// built for another scale is built again at the first frame. Returns whether the line was this key.
bool readLayoutScaleLine(Editor& editor, std::string_view text) {
    std::string const key = std::string(ui::kLayoutScaleKey) + "=";
    if (text.substr(0, key.size()) != key) return false;
    std::string const value(text.substr(key.size()));
    char* end = nullptr;
    float const scale = std::strtof(value.c_str(), &end);
    if (value.empty() || *end != '\0' || !std::isfinite(scale) || scale <= 0.0f) {
        ui::logMessage(editor.state.log,
                       editor.style.iniPath + ": LayoutScale \"" + value +
                           "\" is not a positive number; the window layout is kept as saved.",
                       true);
        return true;
    }
    editor.state.layout.builtScale = scale;
    return true;
}

void readViewSettingsLine(ImGuiContext*, ImGuiSettingsHandler* handler, void*, char const* line) {
    auto& editor = *static_cast<Editor*>(handler->UserData);
    std::string_view const text(line);
    if (readLayoutScaleLine(editor, text)) return;
    std::string const key = std::string(ui::kUiScaleKey) + "=";
    if (text.substr(0, key.size()) != key) return;
    std::string error;
    auto const scale =
        ui::parseUiScale(text.substr(key.size()), editor.style.iniPath + ": " + key.substr(0, key.size() - 1), &error);
    if (!scale) {
        std::string const sentence =
            error + "; the UI stays at scale " + ui::uiScaleText(editor.state.layout.scale.current) + ".";
        ui::logMessage(editor.state.log, sentence, true);
        return;
    }
    ui::UiScaleState& state = editor.state.layout.scale;
    state.saved = *scale;
    if (!state.fromCommandLine) state.current = *scale;
}

void writeViewSettings(ImGuiContext*, ImGuiSettingsHandler* handler, ImGuiTextBuffer* out) {
    auto const& editor = *static_cast<Editor const*>(handler->UserData);
    out->appendf("[gbuffer-lab][View]\n%s\n", ui::uiScaleLine(editor.state.layout.scale.saved).c_str());
    if (editor.state.layout.builtScale > 0.0f)
        out->appendf("%s=%s\n", ui::kLayoutScaleKey.data(), ui::uiScaleText(editor.state.layout.builtScale).c_str());
    out->append("\n");
}

}  // namespace

void addViewSettingsHandler(Editor& editor) {
    ImGuiSettingsHandler handler;
    handler.TypeName = "gbuffer-lab";
    handler.TypeHash = ImHashStr("gbuffer-lab");
    handler.ReadOpenFn = readViewSettingsOpen;
    handler.ReadLineFn = readViewSettingsLine;
    handler.WriteAllFn = writeViewSettings;
    handler.UserData = &editor;
    ImGui::GetCurrentContext()->SettingsHandlers.push_back(handler);
}

}  // namespace gbl
