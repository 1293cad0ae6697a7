// Input queue, shortcut lookup, per-frame translation into editor actions and ImGui 1.86 pacing.
#include "model/input_events.h"

#include <algorithm>
#include <cstdio>

namespace gbl::ui {

namespace {

bool validKey(int key) {
    return key >= 0 && key <= keys::Last;
}
bool validButton(int button) {
    return button >= 0 && button < kMouseButtons;
}

int modifierBit(int key) {
    switch (key) {
        case keys::LeftShift:
        case keys::RightShift:
            return kModShift;
        case keys::LeftControl:
        case keys::RightControl:
            return kModControl;
        case keys::LeftAlt:
        case keys::RightAlt:
            return kModAlt;
        case keys::LeftSuper:
        case keys::RightSuper:
            return kModSuper;
        default:
            return 0;
    }
}

// Modifier bits from the modifier keys that are down (a key event's own mods say the same in
// GLFW, but this also covers the moment a modifier itself is released).
int modsFromKeys(std::array<bool, keys::Last + 1> const& down) {
    int mods = 0;
    for (int key : {keys::LeftShift, keys::RightShift, keys::LeftControl, keys::RightControl, keys::LeftAlt,
                    keys::RightAlt, keys::LeftSuper, keys::RightSuper})
        if (down[std::size_t(key)]) mods |= modifierBit(key);
    return mods;
}

bool inScope(Shortcut const& s, InputContext const& context) {
    if (context.textInput) return false;
    return s.scope == ShortcutScope::Editor || context.viewportHovered;
}

glm::vec3 flyDirection(EditorAction action) {
    switch (action) {
        case EditorAction::FlyForward:
            return {0, 0, 1};
        case EditorAction::FlyBack:
            return {0, 0, -1};
        case EditorAction::FlyLeft:
            return {-1, 0, 0};
        case EditorAction::FlyRight:
            return {1, 0, 0};
        case EditorAction::FlyUp:
            return {0, 1, 0};
        case EditorAction::FlyDown:
            return {0, -1, 0};
        default:
            return {0, 0, 0};
    }
}

Shortcut const* flyShortcut(int key) {
    for (Shortcut const& s : kShortcuts)
        if (s.held && s.key == key) return &s;
    return nullptr;
}

}  // namespace

glm::dvec2 wheelNotches(glm::dvec2 delta, int deltaMode) {
    double const perNotch = deltaMode == 1   ? kWheelLinesPerNotch
                            : deltaMode == 2 ? kWheelPagesPerNotch
                                             : kWheelPixelsPerNotch;
    // A page scrolls down for a positive delta: the wheel turned down. 0 - x, not -x: no axis
    // reads -0.00 where the desktop's reads 0.00.
    return glm::dvec2(0.0) - delta / perNotch;
}

std::string describeEvent(InputEvent const& e) {
    char text[96];
    char const* action = e.action == kPress ? "press" : e.action == kRelease ? "release" : "repeat";
    switch (e.kind) {
        case InputKind::Key:
            std::snprintf(text, sizeof text, "key %d %s mods %d", e.code, action, e.mods);
            break;
        case InputKind::MouseButton:
            std::snprintf(text, sizeof text, "button %d %s mods %d", e.code, action, e.mods);
            break;
        case InputKind::Char:
            std::snprintf(text, sizeof text, "char %u", unsigned(e.code));
            break;
        case InputKind::Scroll:
            std::snprintf(text, sizeof text, "scroll %.2f %.2f", e.value.x, e.value.y);
            break;
        case InputKind::Cursor:
            std::snprintf(text, sizeof text, "cursor %.0f %.0f", e.value.x, e.value.y);
            break;
        case InputKind::Focus:
            std::snprintf(text, sizeof text, "focus %s", e.code ? "gained" : "lost");
            break;
    }
    return text;
}

void InputQueue::push(InputEvent event, double now) {
    event.earliest = lastTake_;
    event.time = now;
    events_.push_back(event);
}

std::vector<InputEvent> InputQueue::take(double now) {
    lastTake_ = now;
    std::vector<InputEvent> out;
    out.swap(events_);
    return out;
}

std::string shortcutHelp(Shortcut const& s) {
    std::string out(s.help);
    for (std::size_t i = 0; i < s.choices.size(); ++i) out += (i == 0 ? " (" : ", ") + std::string(s.choices[i]);
    if (!s.choices.empty()) out += ")";
    return out;
}

Shortcut const& shortcutFor(EditorAction action) {
    for (Shortcut const& s : kShortcuts)
        if (s.action == action) return s;
    return kShortcuts.front();  // unreachable: input_events_test checks every action has an entry
}

std::string_view actionName(EditorAction action) {
    switch (action) {
        case EditorAction::Undo:
            return "undo";
        case EditorAction::Redo:
            return "redo";
        case EditorAction::SaveSession:
            return "save-session";
        case EditorAction::OpenSession:
            return "open-session";
        case EditorAction::OpenScene:
            return "open-scene";
        case EditorAction::NewSession:
            return "new-session";
        case EditorAction::Quit:
            return "quit";
        case EditorAction::FrameSelection:
            return "frame-selection";
        case EditorAction::HomeView:
            return "home-view";
        case EditorAction::ToggleInspectorLock:
            return "toggle-inspector-lock";
        case EditorAction::ShowShortcuts:
            return "show-shortcuts";
        case EditorAction::AccumulatePrevious:
            return "accumulate-previous";
        case EditorAction::AccumulateNext:
            return "accumulate-next";
        case EditorAction::NextView:
            return "next-view";
        case EditorAction::PreviousView:
            return "previous-view";
        case EditorAction::NextLightingMode:
            return "next-lighting-mode";
        case EditorAction::NextCullMode:
            return "next-cull-mode";
        case EditorAction::NextDepthCopy:
            return "next-depth-copy";
        case EditorAction::ToggleOverview:
            return "toggle-overview";
        case EditorAction::TogglePresentation:
            return "toggle-presentation";
        case EditorAction::FlyForward:
            return "fly-forward";
        case EditorAction::FlyBack:
            return "fly-back";
        case EditorAction::FlyLeft:
            return "fly-left";
        case EditorAction::FlyRight:
            return "fly-right";
        case EditorAction::FlyUp:
            return "fly-up";
        case EditorAction::FlyDown:
            return "fly-down";
    }
    return "?";
}

FrameActions translateInput(InputTracker& tracker, std::span<InputEvent const> events, InputContext const& context) {
    FrameActions out;
    double const frameSeconds = std::max(context.frameEnd - context.frameStart, 1e-6);
    // Seconds each fly key was held (and counted) within this frame.
    std::array<double, keys::Last + 1> heldSeconds{};
    auto const flyAllowed = [&] { return !context.textInput && (tracker.mods & kFlyBlockingMods) == 0; };

    for (InputEvent const& e : events) {
        if (e.kind != InputKind::Key || !validKey(e.code)) continue;
        std::size_t const k = std::size_t(e.code);
        if (e.action == kRepeat) continue;  // auto-repeat neither re-triggers taps nor changes held time
        bool const press = e.action == kPress;
        bool const wasFlying = tracker.flying[k];
        if (!press && wasFlying) {
            // Held from the later of its press and the frame start until now; a tap whose press and
            // release came in one poll has no measurable length and gets the minimum.
            double const from = std::max(tracker.downSince[k], context.frameStart);
            double held = std::max(e.time - from, 0.0);
            if (tracker.downSince[k] >= context.frameStart) held = std::max(held, kMinTapSeconds);
            heldSeconds[k] += held;
            out.applied.push_back(describeEvent(e));
        }
        tracker.down[k] = press;
        tracker.flying[k] = false;
        tracker.mods = modsFromKeys(tracker.down);

        if (int const bit = modifierBit(e.code); bit != 0) {
            // A Ctrl/Alt/Super going down stops every fly key for the rest of its press.
            if (press && (bit & kFlyBlockingMods)) {
                for (std::size_t f = 0; f < tracker.flying.size(); ++f) {
                    if (!tracker.flying[f]) continue;
                    heldSeconds[f] += std::max(e.time - std::max(tracker.downSince[f], context.frameStart), 0.0);
                    tracker.flying[f] = false;
                }
            }
            continue;
        }
        if (!press) continue;
        int const mods = e.mods & kShortcutMods;
        for (Shortcut const& s : kShortcuts) {
            if (s.key != e.code || s.held || s.mods != mods || !inScope(s, context)) continue;
            out.taps.push_back(s.action);
            out.applied.push_back(describeEvent(e) + " -> " + std::string(actionName(s.action)));
        }
        if (flyShortcut(e.code) && (mods & kFlyBlockingMods) == 0 && flyAllowed()) {
            tracker.flying[k] = true;
            tracker.downSince[k] = e.time;
            out.applied.push_back(describeEvent(e) + " -> fly");
        }
    }
    // Keys still held fly until the end of the frame.
    for (std::size_t k = 0; k < tracker.flying.size(); ++k)
        if (tracker.flying[k])
            heldSeconds[k] += std::max(context.frameEnd - std::max(tracker.downSince[k], context.frameStart), 0.0);

    if (context.viewportHovered && !context.textInput) {
        for (Shortcut const& s : kShortcuts)
            if (s.held)
                out.move +=
                    flyDirection(s.action) * float(std::min(heldSeconds[std::size_t(s.key)] / frameSeconds, 1.0));
        out.move = glm::clamp(out.move, glm::vec3(-1.0f), glm::vec3(1.0f));
    }
    out.fast = (tracker.mods & kModShift) != 0;
    return out;
}

bool isDoubleClick(ClickTracker& tracker, InputEvent const& press, glm::dvec2 position) {
    glm::dvec2 const d = position - tracker.position;
    bool const isDouble = !tracker.wasDouble && press.code == tracker.button &&
                          press.earliest - tracker.time <= kDoubleClickSeconds &&
                          d.x * d.x + d.y * d.y <= kDoubleClickPixels * kDoubleClickPixels;
    tracker.button = press.code;
    tracker.time = press.time;
    tracker.position = position;
    tracker.wasDouble = isDouble;
    return isDouble;
}

ReplayFrame replayFrame(InputReplay& replay, std::span<InputEvent const> incoming) {
    replay.pending.insert(replay.pending.end(), incoming.begin(), incoming.end());
    ReplayFrame out;
    std::array<bool, keys::Last + 1> keyChanged{};
    std::array<bool, kMouseButtons> buttonChanged{};
    bool anyButtonChanged = false;
    bool pointerMoved = false;
    while (!replay.pending.empty()) {
        InputEvent const e = replay.pending.front();
        if (e.kind == InputKind::Key && validKey(e.code) && e.action != kRepeat) {
            if (keyChanged[std::size_t(e.code)]) break;
            keyChanged[std::size_t(e.code)] = true;
            replay.keysDown[std::size_t(e.code)] = e.action == kPress;
            replay.mods = modsFromKeys(replay.keysDown);
        } else if (e.kind == InputKind::MouseButton && validButton(e.code)) {
            if (buttonChanged[std::size_t(e.code)]) break;
            // A press in the frame the pointer jumped to it would read the jump as a drag.
            if (e.action == kPress && pointerMoved) break;
            buttonChanged[std::size_t(e.code)] = true;
            anyButtonChanged = true;
            bool const press = e.action == kPress;
            replay.buttons[std::size_t(e.code)] = press;
            if (press && isDoubleClick(replay.clicks, e, replay.mouse)) out.doubleClicked[std::size_t(e.code)] = true;
        } else if (e.kind == InputKind::Cursor) {
            // A move after a press or release this frame would put that click somewhere else.
            if (anyButtonChanged) break;
            pointerMoved = pointerMoved || e.value != replay.mouse;
            replay.mouse = e.value;
        } else if (e.kind == InputKind::Scroll) {
            out.scroll += e.value;
        } else if (e.kind == InputKind::Char) {
            out.chars.push_back(unsigned(e.code));
        } else if (e.kind == InputKind::Focus) {
            replay.focused = e.code != 0;
            if (!replay.focused) {
                // Keys released while the window had no focus are never reported: forget them.
                replay.keysDown.fill(false);
                replay.buttons.fill(false);
                replay.mods = 0;
            }
        }
        out.events.push_back(e);
        replay.pending.pop_front();
    }
    return out;
}

}  // namespace gbl::ui
