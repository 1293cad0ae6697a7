// The input queue, the shortcut table and the per-frame translation: taps shorter than a frame act
// once, modified shortcuts never trigger the plain key, fly keys need the viewport, double clicks
// follow event times, and the ImGui 1.86 replay gives each press and release its own frame.
#include "model/input_events.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace gbl::ui;

namespace {

InputEvent key(int code, int action, int mods = 0) {
    InputEvent e;
    e.kind = InputKind::Key;
    e.code = code;
    e.action = action;
    e.mods = mods;
    return e;
}

InputEvent button(int b, int action) {
    InputEvent e;
    e.kind = InputKind::MouseButton;
    e.code = b;
    e.action = action;
    return e;
}

InputEvent cursor(double x, double y) {
    InputEvent e;
    e.kind = InputKind::Cursor;
    e.value = {x, y};
    return e;
}

// One frame: events pushed at `pollTime` (all in one poll, as glfwPollEvents delivers them),
// taken at `pollTime`, translated with the previous take as the frame start.
struct Frames {
    InputQueue queue;
    InputTracker tracker;
    double last = 0.0;
    FrameActions frame(std::vector<InputEvent> events, double pollTime, bool hovered = true, bool text = false) {
        for (auto const& e : events) queue.push(e, pollTime);
        std::vector<InputEvent> const taken = queue.take(pollTime);
        InputContext context{hovered, text, last, pollTime};
        last = pollTime;
        return translateInput(tracker, taken, context);
    }
};

}  // namespace

TEST(InputEvents, EveryActionHasOneShortcutAndNoTwoShareKeyAndMods) {
    std::set<std::pair<int, int>> seen;
    for (Shortcut const& s : kShortcuts) {
        EXPECT_TRUE(seen.insert({s.key, s.mods}).second) << s.keys;
        EXPECT_EQ(shortcutFor(s.action).keys, s.keys);
        EXPECT_FALSE(s.help.empty());
        EXPECT_NE(actionName(s.action), "?");
    }
    // Every enumerator up to the last one appears in the table.
    for (int a = 0; a <= int(EditorAction::FlyDown); ++a) {
        bool found = false;
        for (Shortcut const& s : kShortcuts) found |= s.action == EditorAction(a);
        EXPECT_TRUE(found) << actionName(EditorAction(a));
    }
}

TEST(InputEvents, QueueStampsEventsWithTheirPollAndThePreviousTake) {
    InputQueue q;
    q.take(1.0);
    q.push(key(keys::F, kPress), 1.3);
    q.push(key(keys::F, kRelease), 1.3);
    auto const events = q.take(1.3);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_DOUBLE_EQ(events[0].earliest, 1.0);
    EXPECT_DOUBLE_EQ(events[0].time, 1.3);
    EXPECT_TRUE(q.empty());
    EXPECT_TRUE(q.take(1.6).empty());
}

TEST(InputEvents, ATapBetweenTwoFramesActsExactlyOnce) {
    Frames f;
    f.frame({}, 0.3);
    FrameActions const a = f.frame({key(keys::F, kPress), key(keys::F, kRelease)}, 0.6);
    ASSERT_EQ(a.taps.size(), 1u);
    EXPECT_EQ(a.taps[0], EditorAction::FrameSelection);
    EXPECT_TRUE(f.frame({}, 0.9).taps.empty());
    // Three Ctrl+Z taps of 100 ms within one slow frame: three undos.
    FrameActions const z = f.frame(
        {key(keys::LeftControl, kPress, kModControl), key(keys::Z, kPress, kModControl),
         key(keys::Z, kRelease, kModControl), key(keys::Z, kPress, kModControl), key(keys::Z, kRelease, kModControl),
         key(keys::Z, kPress, kModControl), key(keys::Z, kRelease, kModControl), key(keys::LeftControl, kRelease)},
        1.2);
    EXPECT_EQ(z.taps, std::vector<EditorAction>(3, EditorAction::Undo));
}

TEST(InputEvents, KeyRepeatDoesNotRetrigger) {
    Frames f;
    FrameActions const a = f.frame({key(keys::L, kPress), key(keys::L, kRepeat), key(keys::L, kRepeat)}, 0.1);
    EXPECT_EQ(a.taps, std::vector<EditorAction>{EditorAction::ToggleInspectorLock});
}

TEST(InputEvents, CtrlSSavesAndDoesNotFlyBack) {
    Frames f;
    FrameActions const a =
        f.frame({key(keys::LeftControl, kPress, kModControl), key(keys::S, kPress, kModControl)}, 0.2);
    EXPECT_EQ(a.taps, std::vector<EditorAction>{EditorAction::SaveSession});
    EXPECT_EQ(a.move, glm::vec3(0.0f));
    // Ctrl let go while S is still held: S was pressed for the save, it still must not fly.
    FrameActions const b = f.frame({key(keys::LeftControl, kRelease)}, 0.4);
    EXPECT_EQ(b.move, glm::vec3(0.0f));
    FrameActions const c = f.frame({key(keys::S, kRelease)}, 0.6);
    EXPECT_EQ(c.move, glm::vec3(0.0f));
    EXPECT_TRUE(c.taps.empty());
}

TEST(InputEvents, PlainSDoesNotSaveAndCtrlShiftODoesNotOpenASession) {
    Frames f;
    FrameActions const a = f.frame({key(keys::S, kPress), key(keys::S, kRelease)}, 0.2);
    EXPECT_TRUE(a.taps.empty());
    FrameActions const b = f.frame({key(keys::O, kPress, kModControl | kModShift)}, 0.4);
    EXPECT_EQ(b.taps, std::vector<EditorAction>{EditorAction::OpenScene});
}

TEST(InputEvents, ShortcutsWaitWhileATextFieldHasTheKeyboard) {
    Frames f;
    FrameActions const a = f.frame({key(keys::F, kPress), key(keys::W, kPress)}, 0.2, true, true);
    EXPECT_TRUE(a.taps.empty());
    EXPECT_EQ(a.move, glm::vec3(0.0f));
}

TEST(InputEvents, HeldFlyKeyMovesForTheShareOfTheFrameItWasDown) {
    Frames f;
    f.frame({}, 1.0);
    // Pressed at the poll of 1.0..1.25 (counted from its poll), held over the next frame.
    FrameActions const a = f.frame({key(keys::W, kPress)}, 1.25);
    EXPECT_EQ(a.move, glm::vec3(0.0f)) << "pressed at the end of the frame: no time held yet";
    FrameActions const b = f.frame({}, 1.5);
    EXPECT_FLOAT_EQ(b.move.z, 1.0f);
    FrameActions const c = f.frame({key(keys::W, kRelease)}, 1.75);
    EXPECT_FLOAT_EQ(c.move.z, 1.0f) << "released at this poll: held the whole frame";
    EXPECT_FLOAT_EQ(f.frame({}, 2.0).move.z, 0.0f);
}

TEST(InputEvents, AFlyTapShorterThanAFrameMovesOnce) {
    Frames f;
    f.frame({}, 1.0);
    FrameActions const a = f.frame({key(keys::D, kPress), key(keys::D, kRelease)}, 1.3);
    // Press and release in one poll: the minimum tap, as a share of the 0.3 s frame.
    EXPECT_NEAR(a.move.x, kMinTapSeconds / 0.3, 1e-6);
    EXPECT_FLOAT_EQ(f.frame({}, 1.6).move.x, 0.0f);
}

TEST(InputEvents, FlyKeysNeedTheViewportAndNoCtrl) {
    Frames f;
    f.frame({}, 1.0);
    EXPECT_EQ(f.frame({key(keys::W, kPress)}, 1.2, false).move, glm::vec3(0.0f));
    EXPECT_EQ(f.frame({}, 1.4, false).move, glm::vec3(0.0f)) << "not hovered";
    EXPECT_FLOAT_EQ(f.frame({}, 1.6, true).move.z, 1.0f) << "hovered again with W held";
    // Ctrl goes down while flying: W stops and stays stopped after Ctrl is released.
    FrameActions const c = f.frame({key(keys::LeftControl, kPress, kModControl)}, 1.8);
    EXPECT_FLOAT_EQ(c.move.z, 1.0f) << "until the Ctrl press, which came at the end of the frame";
    EXPECT_EQ(f.frame({}, 2.0).move, glm::vec3(0.0f));
    EXPECT_EQ(f.frame({key(keys::LeftControl, kRelease)}, 2.2).move, glm::vec3(0.0f));
}

TEST(InputEvents, ShiftFliesFaster) {
    Frames f;
    FrameActions const a = f.frame({key(keys::LeftShift, kPress, kModShift), key(keys::W, kPress, kModShift)}, 0.2);
    EXPECT_TRUE(a.fast);
    EXPECT_GT(f.frame({}, 0.4).move.z, 0.0f);
}

TEST(InputEvents, DoubleClickFollowsEventTimesAtAnyFrameRate) {
    InputEvent p = button(0, kPress);
    // Two presses delivered by one poll at 3 fps: they can have been close together.
    ClickTracker t;
    p.earliest = 0.0, p.time = 0.33;
    EXPECT_FALSE(isDoubleClick(t, p, {100, 100}));
    EXPECT_TRUE(isDoubleClick(t, p, {101, 100}));
    // A third press is not another double click.
    EXPECT_FALSE(isDoubleClick(t, p, {101, 100}));

    // At 60 fps, presses 0.5 s apart are two single clicks, 0.2 s apart a double click.
    ClickTracker u;
    p.earliest = 1.0, p.time = 1.016;
    EXPECT_FALSE(isDoubleClick(u, p, {10, 10}));
    p.earliest = 1.5, p.time = 1.516;
    EXPECT_FALSE(isDoubleClick(u, p, {10, 10}));
    p.earliest = 1.7, p.time = 1.716;
    EXPECT_TRUE(isDoubleClick(u, p, {10, 10}));
    // Far apart on screen: not a double click however quick.
    p.earliest = 3.0, p.time = 3.016;
    EXPECT_FALSE(isDoubleClick(u, p, {10, 10}));
    p.earliest = 3.016, p.time = 3.032;
    EXPECT_FALSE(isDoubleClick(u, p, {40, 10}));
}

TEST(InputEvents, ReplayGivesAClickWithinOneFrameItsOwnFramesAtItsPlace) {
    InputReplay r;
    // Move to the button, press, release, move away: all in one poll.
    std::vector<InputEvent> const poll{cursor(50, 60), button(0, kPress), button(0, kRelease), cursor(300, 300)};
    ReplayFrame const f1 = replayFrame(r, poll);
    EXPECT_EQ(r.mouse, glm::dvec2(50, 60));
    EXPECT_FALSE(r.buttons[0]) << "not in the frame the pointer jumped: ImGui would read the jump as a drag";
    EXPECT_EQ(f1.events.size(), 1u);
    replayFrame(r, {});
    EXPECT_TRUE(r.buttons[0]) << "the press, alone in its frame";
    EXPECT_EQ(r.mouse, glm::dvec2(50, 60)) << "at the place it happened";
    ReplayFrame const f3 = replayFrame(r, {});
    EXPECT_FALSE(r.buttons[0]) << "the release the next frame";
    EXPECT_EQ(r.mouse, glm::dvec2(50, 60)) << "still where it was released";
    EXPECT_EQ(f3.events.size(), 1u);
    replayFrame(r, {});
    EXPECT_EQ(r.mouse, glm::dvec2(300, 300));
    EXPECT_TRUE(r.pending.empty());
    // A press where the pointer already is needs no extra frame.
    replayFrame(r, std::vector<InputEvent>{cursor(300, 300), button(1, kPress)});
    EXPECT_TRUE(r.buttons[1]);
}

TEST(InputEvents, ReplayDeliversADoubleClickAndFlagsTheSecondPress) {
    InputReplay r;
    std::vector<InputEvent> poll{cursor(20, 20), button(0, kPress), button(0, kRelease), button(0, kPress),
                                 button(0, kRelease)};
    for (auto& e : poll) e.earliest = 0.0, e.time = 0.4;  // one poll at 2.5 fps
    int presses = 0, doubles = 0;
    for (int frame = 0; frame < 8; ++frame) {
        bool const before = r.buttons[0];
        ReplayFrame const f =
            replayFrame(r, frame == 0 ? std::span<InputEvent const>(poll) : std::span<InputEvent const>());
        if (!before && r.buttons[0]) ++presses;
        doubles += f.doubleClicked[0];
    }
    EXPECT_EQ(presses, 2);
    EXPECT_EQ(doubles, 1);
}

TEST(InputEvents, ReplayKeepsATapOfAKeyOverTwoFrames) {
    InputReplay r;
    std::vector<InputEvent> const poll{key(keys::LeftControl, kPress, kModControl), key(keys::Z, kPress, kModControl),
                                       key(keys::Z, kRelease, kModControl), key(keys::LeftControl, kRelease)};
    replayFrame(r, poll);
    EXPECT_TRUE(r.keysDown[keys::Z]);
    EXPECT_EQ(r.mods, kModControl);
    replayFrame(r, {});
    EXPECT_FALSE(r.keysDown[keys::Z]);
    EXPECT_EQ(r.mods, 0);
}

TEST(InputEvents, DescribeNamesTheEvent) {
    EXPECT_EQ(describeEvent(key(keys::F, kPress)), "key 70 press mods 0");
    EXPECT_EQ(describeEvent(button(1, kRelease)), "button 1 release mods 0");
}

TEST(InputEvents, ProjectorKeysStepViewLightingCullAndBlit) {
    Frames f;
    FrameActions const a = f.frame({key(keys::V, kPress), key(keys::V, kRelease), key(keys::V, kPress, kModShift),
                                    key(keys::M, kPress), key(keys::C, kPress), key(keys::B, kPress)},
                                   0.2, false);
    EXPECT_EQ(a.taps, (std::vector<EditorAction>{EditorAction::NextView, EditorAction::PreviousView,
                                                 EditorAction::NextLightingMode, EditorAction::NextCullMode,
                                                 EditorAction::NextDepthCopy}));
    EXPECT_EQ(a.move, glm::vec3(0.0f));
    // They wait, like the others, while a text field has the keyboard.
    FrameActions const b = f.frame({key(keys::M, kPress)}, 0.4, true, true);
    EXPECT_TRUE(b.taps.empty());
}

TEST(InputEvents, BrowserWheelDeltasBecomeTheDesktopsNotches) {
    // One notch towards the user (the page would scroll down) in each of the browser's units.
    EXPECT_EQ(wheelNotches({0.0, 100.0}, 0), glm::dvec2(0.0, -1.0));  // Chromium: 100 pixels
    EXPECT_EQ(wheelNotches({0.0, 3.0}, 1), glm::dvec2(0.0, -1.0));    // Firefox: 3 lines
    EXPECT_EQ(wheelNotches({0.0, 1.0}, 2), glm::dvec2(0.0, -1.0));    // one screen at a time
    // Away from the user: the desktop's +1, as X11's button 4.
    EXPECT_EQ(wheelNotches({0.0, -100.0}, 0), glm::dvec2(0.0, 1.0));
    EXPECT_EQ(wheelNotches({0.0, -6.0}, 1), glm::dvec2(0.0, 2.0));
    // Sideways: right is negative on the desktop too (GLFW's button 7 gives -1).
    EXPECT_EQ(wheelNotches({100.0, 0.0}, 0), glm::dvec2(-1.0, 0.0));
    // The still axis is +0, as the desktop's: the frame log writes -0 as "-0.00".
    EXPECT_FALSE(std::signbit(wheelNotches({0.0, 100.0}, 0).x));
    // A touchpad's small steps stay small, not a whole notch each.
    EXPECT_DOUBLE_EQ(wheelNotches({0.0, 4.0}, 0).y, -0.04);
}

// The keys that step through a setting list its choices from the setting's table, in its order.
TEST(InputEvents, SteppingShortcutsListTheirSettingsChoicesFromTheTable) {
    EXPECT_EQ(shortcutHelp(shortcutFor(EditorAction::NextDepthCopy)),
              "next depth copy: how depth reaches the lit target (" + std::string(gbl::kDepthCopyNames[0]) + ", " +
                  std::string(gbl::kDepthCopyNames[1]) + ", " + std::string(gbl::kDepthCopyNames[2]) + ")");
    EXPECT_EQ(shortcutHelp(shortcutFor(EditorAction::NextDepthCopy)),
              "next depth copy: how depth reaches the lit target (blit, shader, off)");
    EXPECT_EQ(shortcutFor(EditorAction::NextLightingMode).choices.size(), gbl::kLightingModeNames.size());
    EXPECT_EQ(shortcutFor(EditorAction::NextCullMode).choices.data(), gbl::kCullModeNames.data());
    EXPECT_EQ(shortcutHelp(shortcutFor(EditorAction::Undo)), "undo the last edit");  // no choices, no brackets
}
