// UI scale (issue 26): a bigger editor for a projector. The accepted range, the View menu's
// choices, and the values as the command line and the layout file write them. No ImGui.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace gbl::ui {

inline constexpr float kUiScaleMin = 0.75f;
inline constexpr float kUiScaleMax = 3.0f;

struct UiScaleChoice {
    float scale;
    char const* label;
};
// The View menu's choices; any value in range is accepted from the command line or the layout file.
inline constexpr std::array<UiScaleChoice, 4> kUiScaleChoices{{
    {1.0f, "1x"},
    {1.25f, "1.25x"},
    {1.5f, "1.5x (projector)"},
    {2.0f, "2x"},
}};

// The scale in use and a change asked for: the menu asks during a frame, the editor applies it
// before the next one (the font atlas cannot change mid-frame).
struct UiScaleState {
    float current = 1.0f;
    std::optional<float> requested;
    bool fromCommandLine = false;  // --ui-scale given: it wins over the layout file's value
    // What the layout file keeps: its value as read, then the menu's choices. A --ui-scale is for
    // this run only and is not written over it.
    float saved = 1.0f;
};

// "1.5" -> 1.5 when the whole text is a number in [kUiScaleMin, kUiScaleMax]; else nullopt and,
// when `error` is given, one sentence naming `what` (the option or the file) and the range.
std::optional<float> parseUiScale(std::string_view text, std::string_view what, std::string* error = nullptr);

// A pixel size given at scale 1, at `scale` (whole pixels, so tiles still share edges).
float scaledPixels(float pixels, float scale);

// The scale as a person reads it: "1.5".
std::string uiScaleText(float scale);

// The scale's line in the layout file ("UiScale=1.5") and its reading; the key is kUiScaleKey.
inline constexpr std::string_view kUiScaleKey = "UiScale";
std::string uiScaleLine(float scale);
// The layout file's line naming the scale the saved dock tree was built for (model/layout_state.h,
// LayoutState::builtScale): "LayoutScale=1.5".
inline constexpr std::string_view kLayoutScaleKey = "LayoutScale";

}  // namespace gbl::ui
