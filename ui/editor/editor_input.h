// The editor's input path: GLFW callbacks queue every key, button, character, scroll and pointer
// event (model/input_events.h); each frame the queue is taken once, paced for ImGui and turned
// into editor actions. Replaces polling keys with glfwGetKey once per frame.
#pragma once

#include "model/input_events.h"

#include <string>
#include <vector>

struct GLFWwindow;

namespace gbl {

struct EditorInput {
    ui::InputQueue queue;
    ui::InputTracker tracker;                 // held keys, for the shortcuts and fly keys
    ui::InputReplay replay;                   // what ImGui has been shown so far
    std::vector<ui::InputEvent> frameEvents;  // taken this frame, oldest first
    ui::ReplayFrame imguiFrame;               // this frame's share for ImGui
    double frameStart = 0.0;                  // the previous take
    double frameEnd = 0.0;                    // this take
};

// Installs the editor's callbacks on `window`. ImGui's GLFW backend must have been initialised
// with install_callbacks = false: ImGui gets its input from feedImGui*, paced by the replay.
void installInputCallbacks(GLFWwindow* window, EditorInput& input);
void removeInputCallbacks(GLFWwindow* window);

// Takes everything queued since the last frame (call after glfwPollEvents).
void takeFrameInput(EditorInput& input);

// Feeds this frame's share of the events to ImGui's input queue (through the GLFW backend's
// callbacks), before ImGui_ImplGlfw_NewFrame.
void feedImGuiEvents(EditorInput const& input, GLFWwindow* window);
// After ImGui::NewFrame: double clicks decided on event times replace ImGui's frame-time ones.
void markImGuiDoubleClicks(EditorInput const& input);

// The frame's shortcuts and fly keys, given where the pointer and keyboard were.
ui::FrameActions frameActions(EditorInput& input, bool viewportHovered, bool textInput);

// Sleeps `ms` milliseconds while still taking events, so their times stay exact (--frame-sleep-ms).
void sleepTakingEvents(int ms);

}  // namespace gbl
