// What the panels and the keyboard asked for this frame: light picking, the inspector's pixel,
// camera flight, session dialogs and shortcuts, undo and redo.
#include "editor_loop.h"

#include "panels/panel_scene_loading.h"

#include <imgui.h>

namespace gbl {

namespace {

using ui::EditorState;

ui::CameraInput gatherCameraInput(GLFWwindow* window, EditorState const& state, float dt, bool keyboardFree) {
    ui::CameraInput in;
    in.orbitDrag = state.viewport.orbitDrag;
    in.lookDrag = state.viewport.lookDrag;
    in.panDrag = state.viewport.panDrag;
    in.dolly = state.viewport.wheel;
    in.dt = dt;
    in.viewportHeight = float(std::max(state.viewport.size.y, 1));
    // Keys fly the camera while the mouse is over the viewport or a drag started there, and
    // never while a text field has the keyboard.
    bool const flying = keyboardFree && (state.viewport.hovered || state.viewport.lookDrag != glm::vec2(0.0f));
    if (flying) {
        auto key = [&](int k) { return glfwGetKey(window, k) == GLFW_PRESS ? 1.0f : 0.0f; };
        in.move = glm::vec3(key(GLFW_KEY_D) - key(GLFW_KEY_A), key(GLFW_KEY_E) - key(GLFW_KEY_Q),
                            key(GLFW_KEY_W) - key(GLFW_KEY_S));
        in.fast = key(GLFW_KEY_LEFT_SHIFT) > 0.0f || key(GLFW_KEY_RIGHT_SHIFT) > 0.0f;
    }
    return in;
}

// Picking, the inspector's pixel and lock, framing and flying the camera.
void handleViewRequests(Editor& editor, float dt, bool keyboardFree) {
    EditorState& state = editor.state;
    GLFWwindow* window = editor.window();
    ui::PixelInspectorState& inspector = state.inspector;
    if (state.viewport.clickPixel) pickLightAt(state, *editor.renderer, editor.drawn, *state.viewport.clickPixel);
    if (state.gbuffer.showInViewport) state.pipeline.view = *state.gbuffer.showInViewport;
    if (inspector.selectLight >= 0) state.lightsPanel.selected = inspector.selectLight;
    if (!inspector.locked || !inspector.pixel) {
        if (state.viewport.hoverPixel) {
            inspector.pixel = state.viewport.hoverPixel;
            inspector.source = "viewport";
        } else if (state.gbuffer.hoverPixel) {
            inspector.pixel = state.gbuffer.hoverPixel;
            inspector.source = "G-buffer viewer";
        }
    }
    if (keyboardFree && editor.keys.pressed(window, GLFW_KEY_L)) inspector.locked = !inspector.locked;
    bool const frameKey = keyboardFree && editor.keys.pressed(window, GLFW_KEY_F);
    if (state.viewport.frameRequested || frameKey) ui::frameBounds(state.rig, state.camera, state.sceneBounds);
    ui::applyCameraInput(state.rig, state.camera, gatherCameraInput(window, state, dt, keyboardFree));
}

// Sessions, exports, undo and crash recovery (ui/session_controller.h), and their shortcuts.
void handleSessionRequests(Editor& editor, FrameTimes const& times, EditRequest const& edit, bool keyboardFree) {
    EditorState& state = editor.state;
    ui::SessionController& sessions = *editor.sessions;
    GLFWwindow* window = editor.window();
    KeyEdges& keys = editor.keys;
    ui::SessionRequest const request = ui::drawSessionDialogs(sessions.panel);
    if (request.kind != ui::SessionRequestKind::None) {
        FrameExport exported{state.camera, editor.drawn, state.pipeline, times.frameStats, state.sceneTriangles, {}};
        sessions.handle(request, state, *editor.renderer, exported, editor.sceneLoader);
    }
    bool const ctrl = glfwGetKey(window, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS ||
                      glfwGetKey(window, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
    bool const zPressed = keys.pressed(window, GLFW_KEY_Z);
    bool const yPressed = keys.pressed(window, GLFW_KEY_Y);
    bool const sPressed = keys.pressed(window, GLFW_KEY_S);
    bool const oPressed = keys.pressed(window, GLFW_KEY_O);
    if (keyboardFree && ctrl && sPressed) sessions.panel.saveRequested = true;
    // Ctrl+O opens a session, Ctrl+Shift+O a scene.
    bool const shift = glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                       glfwGetKey(window, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
    ui::SceneLoadingState& loading = editor.loading;
    if (keyboardFree && ctrl && shift && oPressed)
        ui::openSceneDialog(loading, loading.recent.empty() ? std::string() : loading.recent.front());
    if (keyboardFree && ctrl && !shift && oPressed)
        ui::openSessionDialog(sessions.panel, ui::SessionDialog::Open,
                              sessions.panel.currentPath.empty() ? "session.json" : sessions.panel.currentPath);
    if (edit.undo || (keyboardFree && ctrl && zPressed)) sessions.undo(state);
    if (edit.redo || (keyboardFree && ctrl && yPressed)) sessions.redo(state);
    // A held slider is one edit: it becomes an undo step when released.
    sessions.afterFrame(state, ImGui::IsAnyItemActive());
}

}  // namespace

void handleRequests(Editor& editor, FrameTimes const& times, EditRequest const& edit) {
    bool const keyboardFree = !ImGui::GetIO().WantTextInput;
    handleViewRequests(editor, times.dt, keyboardFree);
    handleSessionRequests(editor, times, edit, keyboardFree);
}

}  // namespace gbl
