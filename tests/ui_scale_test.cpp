// UI scale (issue 26): the accepted values, the layout file's line, and the command line's refusals.
#include "model/ui_scale.h"
#include "support/run_command.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace gbl::ui;

TEST(UiScale, AcceptsNumbersInRange) {
    EXPECT_EQ(parseUiScale("1.5", "--ui-scale"), 1.5f);
    EXPECT_EQ(parseUiScale("0.75", "--ui-scale"), 0.75f);
    EXPECT_EQ(parseUiScale("3", "--ui-scale"), 3.0f);
    for (UiScaleChoice const& c : kUiScaleChoices)
        EXPECT_EQ(parseUiScale(uiScaleText(c.scale), "x"), c.scale) << c.label;
}

TEST(UiScale, RefusesOtherTextWithOneSentence) {
    for (char const* bad : {"0", "0.5", "3.5", "abc", "", "1.5x", "nan", "inf", "-1"}) {
        std::string error;
        EXPECT_FALSE(parseUiScale(bad, "--ui-scale", &error)) << bad;
        EXPECT_EQ(error.rfind("--ui-scale must be a number between 0.75 and 3", 0), 0u) << error;
        EXPECT_NE(error.find(std::string("'") + bad + "'"), std::string::npos) << error;
    }
}

TEST(UiScale, LayoutFileLineReadsBack) {
    EXPECT_EQ(uiScaleLine(1.5f), "UiScale=1.5");
    EXPECT_EQ(uiScaleLine(1.25f), "UiScale=1.25");
    std::string const line = uiScaleLine(2.0f);
    EXPECT_EQ(parseUiScale(line.substr(kUiScaleKey.size() + 1), "imgui.ini"), 2.0f);
}

TEST(UiScale, PixelsFollowTheScale) {
    EXPECT_EQ(scaledPixels(300.0f, 1.0f), 300.0f);
    EXPECT_EQ(scaledPixels(300.0f, 1.5f), 450.0f);
    EXPECT_EQ(scaledPixels(13.0f, 1.25f), 16.0f);  // whole pixels
}

// The editor refuses a bad --ui-scale before opening a window: exit 2, one line naming the option.
TEST(UiScaleCli, RefusesZeroAndText) {
    for (char const* bad : {"0", "abc", "4"}) {
        auto const r = gbl::test::expectRefused({"--ui-scale", bad}, "--ui-scale");
        EXPECT_NE(r.output.find("between 0.75 and 3"), std::string::npos) << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    }
}
