// The editor's main loop: start-up, then per frame render, UI, requests and present, then shutdown.
// Each step is a named function in ui/editor_*.cpp over the state they share (ui/editor_loop.h).
#include "editor.h"

#include "editor_loop.h"

#include <imgui.h>

namespace gbl {

int runEditor(EditorOptions const& options) {
    Editor editor(options);
    if (auto const exitCode = openWindow(editor)) return *exitCode;
    if (auto const exitCode = startEditor(editor)) return *exitCode;
    initImGui(editor);
    connectScriptHost(editor);

    while (!glfwWindowShouldClose(editor.window()) && !editor.state.quitRequested) {
        FrameTimes times;
        if (!beginFrame(editor, times)) continue;
        renderScene(editor, times);
        reloadShaders(editor);

        auto const uiStart = EditorClock::now();
        EditRequest const edit = drawPanels(editor, times);
        handleRequests(editor, times, edit);
        ImGui::Render();
        times.uiMs = msSince(uiStart);

        present(editor, times);
        recordFrame(editor, times);
    }
    return shutdownEditor(editor);
}

}  // namespace gbl
