// The editor's main loop: start-up, then per frame render, UI, requests and present, then shutdown.
// Each step is a named function in ui/editor_*.cpp over the state they share (ui/editor_loop.h).
// On the desktop the loop is a while loop; in the browser the page's frame callback runs one
// frame at a time (emscripten_set_main_loop), since a loop that never returns would block the page.
#include "editor.h"

#include "editor_loop.h"

#include <imgui.h>

#include <cstdio>
#include <memory>

#ifdef __EMSCRIPTEN__
#include <emscripten/emscripten.h>
#endif

namespace gbl {

namespace {

bool running(Editor& editor) {
    return !glfwWindowShouldClose(editor.window()) && !editor.state.quitRequested;
}

// One frame; true when it rendered the scene.
bool runFrame(Editor& editor) {
    FrameTimes times;
    if (!beginFrame(editor, times)) return false;
    renderScene(editor, times);
    reloadShaders(editor);

    auto const uiStart = EditorClock::now();
    EditRequest const edit = drawPanels(editor, times);
    handleRequests(editor, times, edit);
    ImGui::Render();
    times.uiMs = msSince(uiStart);

    present(editor, times);
    recordFrame(editor, times);
    return times.rendered;
}

#ifdef __EMSCRIPTEN__
// The frames after the scene first rendered that complete the editor: ImGui sizes its windows on
// the frame after it first meets them, and the viewers fit their ranges to what was rendered.
constexpr int kSettlingFrames = 3;

// The page (app/web/index.html) covers the canvas with a loading line until the first complete
// frame, so a quick screenshot never shows a half-drawn editor. The frames before it count the
// shaders' compiling: the Stats window's frame time starts afresh when the editor is shown.
void showPageWhenComplete(Editor& editor, bool rendered) {
    if (editor.pageFramesLeft == 0) return;
    if (editor.pageFramesLeft < 0) {
        if (rendered) editor.pageFramesLeft = kSettlingFrames;
        return;
    }
    if (--editor.pageFramesLeft > 0) return;
    editor.state.stats.count = 0;  // the next frame seeds the average again (ui::recordFrame)
    editor.state.stats.next = 0;
    std::printf("gbuffer-lab: the editor is shown at frame %d, its first complete one\n", int(editor.frame));
    EM_ASM({
        if (Module['gblShowEditor']) Module['gblShowEditor']();
    });
}

// One browser frame; the editor lives until the page goes, unless it quits (--frames, a UI test).
void browserFrame(void* user) {
    auto* editor = static_cast<Editor*>(user);
    bool const wasIdle = editor->idle;
    showPageWhenComplete(*editor, runFrame(*editor));
    // Idle, the page's frame callback runs every third display frame (1/20 s at 60 Hz), as the
    // desktop editor waits up to 1/20 s for an event; back to every frame at the next change.
    if (editor->idle != wasIdle) emscripten_set_main_loop_timing(EM_TIMING_RAF, editor->idle ? 3 : 1);
    if (running(*editor)) return;
    emscripten_cancel_main_loop();
    int const exitCode = shutdownEditor(*editor);
    std::printf("gbuffer-lab: the editor stopped (exit code %d)\n", exitCode);
    delete editor;
}
#endif

}  // namespace

int runEditor(EditorOptions const& options) {
    auto editor = std::make_unique<Editor>(options);
    if (auto const exitCode = openWindow(*editor)) return *exitCode;
    if (auto const exitCode = startEditor(*editor)) return *exitCode;
    initImGui(*editor);
    connectScriptHost(*editor);
#ifdef __EMSCRIPTEN__
    // main returns at once; the runtime stays (EXIT_RUNTIME=0) and the frame callback owns the editor.
    emscripten_set_main_loop_arg(browserFrame, editor.release(), 0, false);
    return 0;
#else
    while (running(*editor)) runFrame(*editor);
    return shutdownEditor(*editor);
#endif
}

}  // namespace gbl
