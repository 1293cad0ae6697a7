// Keyboard and mouse input as GLFW's callbacks deliver it, queued so nothing between two frames is
// lost; the editor's shortcut table; and the steps that turn one frame's events into editor actions
// and into what an ImGui that reads its input once per frame (1.86) can follow. No GLFW, no ImGui.
#pragma once

#include "core/pipeline_settings.h"

#include <glm/glm.hpp>

#include <array>
#include <deque>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gbl::ui {

// GLFW's key codes, action and modifier values (the editor's callbacks static_assert them against
// glfw3.h), so this layer and its tests need no GLFW.
namespace keys {
inline constexpr int Space = 32;
inline constexpr int A = 'A', B = 'B', C = 'C', D = 'D', E = 'E', F = 'F', G = 'G', L = 'L', M = 'M', N = 'N', O = 'O',
                     P = 'P', Q = 'Q', S = 'S', V = 'V', W = 'W', Y = 'Y', Z = 'Z';
inline constexpr int Escape = 256, Enter = 257, Tab = 258, Backspace = 259, Delete = 261;
inline constexpr int Right = 262, Left = 263, Down = 264, Up = 265, Home = 268, End = 269;
inline constexpr int F1 = 290;
inline constexpr int LeftShift = 340, LeftControl = 341, LeftAlt = 342, LeftSuper = 343;
inline constexpr int RightShift = 344, RightControl = 345, RightAlt = 346, RightSuper = 347;
inline constexpr int Last = 348;
}  // namespace keys

inline constexpr int kModShift = 0x1, kModControl = 0x2, kModAlt = 0x4, kModSuper = 0x8;
// The modifiers a shortcut is matched on (Caps Lock and Num Lock bits are ignored).
inline constexpr int kShortcutMods = kModShift | kModControl | kModAlt | kModSuper;
// Modifiers that stop the fly keys: Shift only makes them faster.
inline constexpr int kFlyBlockingMods = kModControl | kModAlt | kModSuper;
inline constexpr int kRelease = 0, kPress = 1, kRepeat = 2;
inline constexpr int kMouseButtons = 5;

enum class InputKind { Key, MouseButton, Char, Scroll, Cursor, Focus };

struct InputEvent {
    InputKind kind = InputKind::Key;
    int code = 0;           // key, mouse button, Unicode code point, or 1/0 for focus gained/lost
    int scancode = 0;       // keys: what GLFW passed along (ImGui 1.87+ backends want it)
    int action = 0;         // keys and buttons: kRelease, kPress, kRepeat
    int mods = 0;           // kMod* bits
    glm::dvec2 value{0.0};  // cursor: position in window coordinates; scroll: offsets
    // When it happened is only known to within a poll: after `earliest` (the previous poll) and
    // no later than `time` (the poll that delivered it), both in seconds of one clock.
    double earliest = 0.0;
    double time = 0.0;
};

// A browser wheel event (WheelEvent's deltaX/deltaY and deltaMode: 0 pixels, 1 lines, 2 pages) as
// the desktop's scroll offsets: one notch of a mouse wheel is 1.0 there (GLFW on X11, Windows and
// macOS alike), positive for the wheel turned up or left, where a page scrolls back. Browsers
// report one notch as 100 pixels (Chromium), 3 lines (Firefox) or 1 page ("one screen at a time");
// a touchpad's small pixel deltas give fractions of a notch, as a desktop touchpad does.
inline constexpr double kWheelPixelsPerNotch = 100.0, kWheelLinesPerNotch = 3.0, kWheelPagesPerNotch = 1.0;
glm::dvec2 wheelNotches(glm::dvec2 delta, int deltaMode);

// "key F press", "button 0 release at 412,300": the --log-frames line's record of an event.
std::string describeEvent(InputEvent const& event);

// Events in the order the callbacks ran. The callbacks run inside glfwPollEvents on the main
// thread, so no locking is needed.
class InputQueue {
public:
    // Stamps the event with `now` and with the time of the last take().
    void push(InputEvent event, double now);
    // Everything queued since the last take, oldest first.
    std::vector<InputEvent> take(double now);
    bool empty() const { return events_.empty(); }

private:
    std::vector<InputEvent> events_;
    double lastTake_ = 0.0;
};

// --- the shortcut table ------------------------------------------------------------------------

enum class EditorAction {
    Undo,
    Redo,
    SaveSession,
    OpenSession,
    OpenScene,
    NewSession,
    Quit,
    FrameSelection,
    HomeView,
    ToggleInspectorLock,
    ShowShortcuts,
    AccumulatePrevious,
    AccumulateNext,
    NextView,
    PreviousView,
    NextLightingMode,
    NextCullMode,
    NextDepthCopy,
    ToggleOverview,
    TogglePresentation,
    FlyForward,
    FlyBack,
    FlyLeft,
    FlyRight,
    FlyUp,
    FlyDown,
};

enum class ShortcutScope {
    Viewport,  // only while the pointer is over the viewport (and no text field has the keyboard)
    Editor,    // anywhere, except while a text field has the keyboard
};

struct Shortcut {
    int key = 0;
    int mods = 0;  // exact: Ctrl+S does not match S, S does not match Ctrl+S
    EditorAction action = EditorAction::Undo;
    ShortcutScope scope = ShortcutScope::Editor;
    bool held = false;      // acts for as long as the key is down (flying) rather than once per press
    std::string_view keys;  // as the Help > Shortcuts window and menus show it
    std::string_view help;
    // A shortcut that steps through a setting's choices: the names, in order, from the setting's
    // own table (core/pipeline_settings.h), which shortcutHelp() lists after `help`.
    std::span<std::string_view const> choices{};
};

// One list: the key handling, the menus' shortcut hints and the Help > Shortcuts window read it.
inline constexpr std::array<Shortcut, 26> kShortcuts{{
    {keys::Z, kModControl, EditorAction::Undo, ShortcutScope::Editor, false, "Ctrl+Z", "undo the last edit"},
    {keys::Y, kModControl, EditorAction::Redo, ShortcutScope::Editor, false, "Ctrl+Y", "redo"},
    {keys::S, kModControl, EditorAction::SaveSession, ShortcutScope::Editor, false, "Ctrl+S", "save the session"},
    {keys::O, kModControl, EditorAction::OpenSession, ShortcutScope::Editor, false, "Ctrl+O", "open a session file"},
    {keys::O, kModControl | kModShift, EditorAction::OpenScene, ShortcutScope::Editor, false, "Ctrl+Shift+O",
     "open a glTF scene"},
    {keys::N, kModControl, EditorAction::NewSession, ShortcutScope::Editor, false, "Ctrl+N",
     "new session: the default scene and settings"},
    {keys::Q, kModControl, EditorAction::Quit, ShortcutScope::Editor, false, "Ctrl+Q", "quit"},
    {keys::F, 0, EditorAction::FrameSelection, ShortcutScope::Editor, false, "F",
     "frame the selected light (the scene from inside when none is selected)"},
    {keys::Home, 0, EditorAction::HomeView, ShortcutScope::Editor, false, "Home", "back to the scene's default view"},
    {keys::L, 0, EditorAction::ToggleInspectorLock, ShortcutScope::Editor, false, "L",
     "lock or unlock the pixel inspector on its pixel"},
    {keys::F1, 0, EditorAction::ShowShortcuts, ShortcutScope::Editor, false, "F1", "show this list"},
    {keys::Left, 0, EditorAction::AccumulatePrevious, ShortcutScope::Editor, false, "Left",
     "light by light: one light fewer (while accumulating)"},
    {keys::Right, 0, EditorAction::AccumulateNext, ShortcutScope::Editor, false, "Right",
     "light by light: one light more (while accumulating)"},
    {keys::V, 0, EditorAction::NextView, ShortcutScope::Editor, false, "V",
     "next view: final, lighting, then each G-buffer attachment"},
    {keys::V, kModShift, EditorAction::PreviousView, ShortcutScope::Editor, false, "Shift+V", "previous view"},
    {keys::M, 0, EditorAction::NextLightingMode, ShortcutScope::Editor, false, "M", "next lighting mode",
     kLightingModeNames},
    {keys::C, 0, EditorAction::NextCullMode, ShortcutScope::Editor, false, "C", "next light-volume cull mode",
     kCullModeNames},
    {keys::B, 0, EditorAction::NextDepthCopy, ShortcutScope::Editor, false, "B",
     "next depth copy: how depth reaches the lit target", kDepthCopyNames},
    {keys::G, 0, EditorAction::ToggleOverview, ShortcutScope::Editor, false, "G",
     "attachment overview: every G-buffer attachment and the lit frame at once (click one to show it)"},
    {keys::P, 0, EditorAction::TogglePresentation, ShortcutScope::Editor, false, "P",
     "presentation layout: the viewport's frame as large as the window, the lesson beside it (P: back)"},
    {keys::W, 0, EditorAction::FlyForward, ShortcutScope::Viewport, true, "W", "fly forward (Shift: faster)"},
    {keys::S, 0, EditorAction::FlyBack, ShortcutScope::Viewport, true, "S", "fly back"},
    {keys::A, 0, EditorAction::FlyLeft, ShortcutScope::Viewport, true, "A", "fly left"},
    {keys::D, 0, EditorAction::FlyRight, ShortcutScope::Viewport, true, "D", "fly right"},
    {keys::E, 0, EditorAction::FlyUp, ShortcutScope::Viewport, true, "E", "fly up"},
    {keys::Q, 0, EditorAction::FlyDown, ShortcutScope::Viewport, true, "Q", "fly down"},
}};

// The table's entry for an action (every action has exactly one; input_events_test checks).
Shortcut const& shortcutFor(EditorAction action);
std::string_view actionName(EditorAction action);
// What the Help > Shortcuts window says a shortcut does: its help, then its choices in brackets.
std::string shortcutHelp(Shortcut const& shortcut);

// --- one frame's events into editor actions ----------------------------------------------------

// What the rest of the editor knew when the frame's events are applied.
struct InputContext {
    bool viewportHovered = false;  // the pointer is over the viewport image
    bool textInput = false;        // a text field has the keyboard (ImGui's WantTextInput)
    double frameStart = 0.0;       // the previous take() of the queue
    double frameEnd = 0.0;         // this take()
};

// Key state carried from frame to frame.
struct InputTracker {
    std::array<bool, keys::Last + 1> down{};
    // A fly key counts while it is down, was pressed with no Ctrl/Alt/Super and none has gone
    // down since: Ctrl+S never flies, not even after Ctrl is let go with S still held.
    std::array<bool, keys::Last + 1> flying{};
    std::array<double, keys::Last + 1> downSince{};
    int mods = 0;
};

struct FrameActions {
    std::vector<EditorAction> taps;  // actions of shortcuts pressed this frame, in order
    // CameraInput::move for this frame: for each axis the share of the frame the key was held
    // (x right, y up, z forward), so a tap shorter than a frame still moves, and moves once.
    glm::vec3 move{0.0f};
    bool fast = false;
    std::vector<std::string> applied;  // describeEvent of every event that did something
};

// A key tap whose press and release arrive in the same poll is held for at least this long:
// the true length is unknown, and a tap must move the camera a little, not nothing.
inline constexpr double kMinTapSeconds = 1.0 / 60.0;

FrameActions translateInput(InputTracker& tracker, std::span<InputEvent const> events, InputContext const& context);

// --- double clicks on event times ----------------------------------------------------------------

inline constexpr double kDoubleClickSeconds = 0.30;
inline constexpr double kDoubleClickPixels = 6.0;

struct ClickTracker {
    int button = -1;
    double time = -1e300;  // latest time the previous press can have happened
    glm::dvec2 position{0.0};
    bool wasDouble = false;  // a triple click is a double click and a single one
};

// Whether a press is the second of a double click: same button, close by, and the two presses
// can have been within kDoubleClickSeconds of each other (times are known to a poll, so at a few
// frames per second two clicks in adjacent polls count). Call for every button press, in order.
bool isDoubleClick(ClickTracker& tracker, InputEvent const& press, glm::dvec2 position);

// --- pacing input for an ImGui that reads state once per frame --------------------------------

// ImGui 1.86 reads the mouse buttons, keys and pointer once per frame, so a press and release
// between two frames, or a press and a move away, are lost. The replay applies the queued events
// to a state ImGui reads, but ends a frame's share before a second change of the same key or
// button, before a pointer move that follows a button change and before a press that follows a
// pointer move: each press and release then reaches ImGui in its own frame, at the place it
// happened, with no pointer jump read as a drag. The rest waits for the next frame.
struct InputReplay {
    std::deque<InputEvent> pending;
    glm::dvec2 mouse{-1.0e9};  // pointer in window coordinates; far away until the first move
    std::array<bool, kMouseButtons> buttons{};
    std::array<bool, keys::Last + 1> keysDown{};
    int mods = 0;
    bool focused = true;
    ClickTracker clicks;
};

struct ReplayFrame {
    std::vector<InputEvent> events;                   // what this frame applies, in order (ImGui 1.87+ takes these)
    std::array<bool, kMouseButtons> doubleClicked{};  // a press this frame that is a double click
    glm::dvec2 scroll{0.0};
    std::vector<unsigned> chars;
};

// Appends `incoming` to what is pending and applies this frame's share to `replay`.
ReplayFrame replayFrame(InputReplay& replay, std::span<InputEvent const> incoming);

}  // namespace gbl::ui
