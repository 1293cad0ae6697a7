// GLFW callbacks into the input queue, and the queue's events into ImGui (either version).
#include "editor_input.h"

#include "panels/gui_util.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

#ifdef __EMSCRIPTEN__
#include <emscripten/html5.h>
#endif

namespace gbl {

namespace {

// The model's key and modifier values are GLFW's; this is where that is checked.
static_assert(ui::keys::F == GLFW_KEY_F && ui::keys::Home == GLFW_KEY_HOME && ui::keys::F1 == GLFW_KEY_F1);
static_assert(ui::keys::Escape == GLFW_KEY_ESCAPE && ui::keys::Tab == GLFW_KEY_TAB);
static_assert(ui::keys::LeftControl == GLFW_KEY_LEFT_CONTROL && ui::keys::RightSuper == GLFW_KEY_RIGHT_SUPER);
static_assert(ui::keys::Last == GLFW_KEY_LAST);
static_assert(ui::kModShift == GLFW_MOD_SHIFT && ui::kModControl == GLFW_MOD_CONTROL && ui::kModAlt == GLFW_MOD_ALT &&
              ui::kModSuper == GLFW_MOD_SUPER);
static_assert(ui::kPress == GLFW_PRESS && ui::kRelease == GLFW_RELEASE && ui::kRepeat == GLFW_REPEAT);

// GLFW's input callbacks carry no closure; the window's user pointer already holds the scene
// loading state (drops), so the one editor window's input lives here.
EditorInput* gInput = nullptr;

void push(ui::InputEvent const& e) {
    if (gInput) gInput->queue.push(e, glfwGetTime());
}

void onKey(GLFWwindow*, int key, int scancode, int action, int mods) {
    ui::InputEvent e;
    e.kind = ui::InputKind::Key;
    e.code = key;
    e.scancode = scancode;
    e.action = action;
    e.mods = mods;
    push(e);
}

void onChar(GLFWwindow*, unsigned codepoint) {
    ui::InputEvent e;
    e.kind = ui::InputKind::Char;
    e.code = int(codepoint);
    push(e);
}

void onMouseButton(GLFWwindow*, int button, int action, int mods) {
    ui::InputEvent e;
    e.kind = ui::InputKind::MouseButton;
    e.code = button;
    e.action = action;
    e.mods = mods;
    push(e);
}

#ifndef __EMSCRIPTEN__
void onScroll(GLFWwindow*, double x, double y) {
    ui::InputEvent e;
    e.kind = ui::InputKind::Scroll;
    e.value = {x, y};
    push(e);
}
#else
// The browser's wheel, read here rather than through GLFW: Emscripten's GLFW hands the scroll
// callback the raw deltaY (pixels, positive as the page scrolls down), about 100 times a desktop
// notch and reversed. The event's deltaMode says its unit; wheelNotches makes it the desktop's.
EM_BOOL onBrowserWheel(int, EmscriptenWheelEvent const* w, void*) {
    ui::InputEvent e;
    e.kind = ui::InputKind::Scroll;
    e.value = ui::wheelNotches({w->deltaX, w->deltaY}, int(w->deltaMode));
    push(e);
    return EM_TRUE;  // the page itself does not scroll
}
#endif

void onCursor(GLFWwindow*, double x, double y) {
    ui::InputEvent e;
    e.kind = ui::InputKind::Cursor;
    e.value = {x, y};
    push(e);
}

void onFocus(GLFWwindow* window, int focused) {
    ui::InputEvent e;
    e.kind = ui::InputKind::Focus;
    e.code = focused;
    push(e);
    ImGui_ImplGlfw_WindowFocusCallback(window, focused);
}

void onCursorEnter(GLFWwindow* window, int entered) {
    ImGui_ImplGlfw_CursorEnterCallback(window, entered);
}

}  // namespace

void installInputCallbacks(GLFWwindow* window, EditorInput& input) {
    gInput = &input;
    glfwSetKeyCallback(window, onKey);
    glfwSetCharCallback(window, onChar);
    glfwSetMouseButtonCallback(window, onMouseButton);
#ifdef __EMSCRIPTEN__
    emscripten_set_wheel_callback("#canvas", nullptr, EM_TRUE, onBrowserWheel);
#else
    glfwSetScrollCallback(window, onScroll);
#endif
    glfwSetCursorPosCallback(window, onCursor);
    glfwSetWindowFocusCallback(window, onFocus);
    glfwSetCursorEnterCallback(window, onCursorEnter);
    input.queue.take(glfwGetTime());
    input.frameEnd = glfwGetTime();
    // The pointer may already be over the window, with no move reported yet.
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window, &x, &y);
    onCursor(window, x, y);
}

void removeInputCallbacks(GLFWwindow* window) {
    glfwSetKeyCallback(window, nullptr);
    glfwSetCharCallback(window, nullptr);
    glfwSetMouseButtonCallback(window, nullptr);
#ifdef __EMSCRIPTEN__
    emscripten_set_wheel_callback("#canvas", nullptr, EM_TRUE, nullptr);
#else
    glfwSetScrollCallback(window, nullptr);
#endif
    glfwSetCursorPosCallback(window, nullptr);
    glfwSetWindowFocusCallback(window, nullptr);
    glfwSetCursorEnterCallback(window, nullptr);
    gInput = nullptr;
}

void takeFrameInput(EditorInput& input) {
    double const now = glfwGetTime();
    input.frameStart = input.frameEnd;
    input.frameEnd = now;
    input.frameEvents = input.queue.take(now);
    input.imguiFrame = ui::replayFrame(input.replay, input.frameEvents);
}

void feedImGuiEvents(EditorInput const& input, GLFWwindow* window) {
    for (ui::InputEvent const& e : input.imguiFrame.events) {
        switch (e.kind) {
            case ui::InputKind::Key:
                ImGui_ImplGlfw_KeyCallback(window, e.code, e.scancode, e.action, e.mods);
                break;
            case ui::InputKind::MouseButton:
                ImGui_ImplGlfw_MouseButtonCallback(window, e.code, e.action, e.mods);
                break;
            case ui::InputKind::Char:
                ImGui_ImplGlfw_CharCallback(window, unsigned(e.code));
                break;
            case ui::InputKind::Scroll:
                // Straight to ImGui: the GLFW backend's scroll callback ignores scrolls under Emscripten's
                // GLFW, expecting the backend's own canvas wheel handler, which the editor replaces
                // (onBrowserWheel: the same notches as the desktop's).
                ImGui::GetIO().AddMouseWheelEvent(float(e.value.x), float(e.value.y));
                break;
            case ui::InputKind::Cursor:
                ImGui_ImplGlfw_CursorPosCallback(window, e.value.x, e.value.y);
                break;
            case ui::InputKind::Focus:
                break;  // forwarded when it happened (onFocus)
        }
    }
}

void markImGuiDoubleClicks(EditorInput const& input) {
    for (int b = 0; b < ui::kMouseButtons; ++b)
        if (input.imguiFrame.doubleClicked[std::size_t(b)]) ui::markDoubleClick(b);
}

ui::FrameActions frameActions(EditorInput& input, bool viewportHovered, bool textInput) {
    ui::InputContext const context{viewportHovered, textInput, input.frameStart, input.frameEnd};
    return ui::translateInput(input.tracker, input.frameEvents, context);
}

void sleepTakingEvents(int ms) {
    double const until = glfwGetTime() + ms / 1000.0;
    for (double now = glfwGetTime(); now < until; now = glfwGetTime()) glfwWaitEventsTimeout(until - now);
}

}  // namespace gbl
