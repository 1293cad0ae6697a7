// The UI script's command table: load-time checks, usage in errors, and help built from the table.
#include "script/ui_script.h"

#include "core/pipeline_fields.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace gbl;
using namespace gbl::ui;
namespace fs = std::filesystem;

namespace {

// Writes `text` as a script file and loads it; the error sentence (empty when it loaded).
std::string loadError(std::string const& text) {
    fs::path const path = fs::temp_directory_path() / ("ui_script_test_" + std::to_string(::getpid()) + ".txt");
    std::ofstream(path) << text;
    std::string error;
    auto const script = UiScript::load(path.string(), &error);
    fs::remove(path);
    EXPECT_EQ(script.has_value(), error.empty()) << error;
    return error;
}

// The help line of a command: "  NAME USAGE   help" (nullopt when it is not listed).
std::optional<std::string> helpLine(std::string const& name) {
    std::istringstream in(uiScriptHelp());
    for (std::string line; std::getline(in, line);)
        if (line.rfind("  " + name + " ", 0) == 0) return line;
    return std::nullopt;
}

}  // namespace

TEST(UiScript, EveryCommandOfTheTestScriptsLoadsAndIsInTheHelp) {
    EXPECT_EQ(loadError("frames 3\nset mode tiled\nlight 0 kq 0.5\nexpect-light 0 kq 0.5\n"
                        "print some free text\nwait-log 5 a log line\nundo\nexpect-window-shown Scene error\n"
                        "skip-unless-exists /a path with spaces\n# a comment\n\n"),
              "");
    for (char const* name : {"frames", "set", "light", "expect-light", "print", "wait-log", "undo", "redo",
                             "expect-window-shown", "skip-unless-exists", "export-viewer", "expect-soak-stable"})
        EXPECT_TRUE(helpLine(name)) << name;
}

TEST(UiScript, ArgumentCountsComeFromTheUsage) {
    EXPECT_NE(loadError("light 0 kq\n").find(":1: wrong number of arguments for light (usage: light I FIELD VALUE)"),
              std::string::npos);
    EXPECT_NE(loadError("frames 1\nframe-scene now\n").find(":2: wrong number of arguments for frame-scene"),
              std::string::npos);
    // A last word with "..." takes the rest of the line, but at least one word.
    EXPECT_NE(loadError("print\n").find("wrong number of arguments for print (usage: print TEXT...)"),
              std::string::npos);
    EXPECT_NE(loadError("wait-log 5\n").find("usage: wait-log SECONDS TEXT..."), std::string::npos);
}

TEST(UiScript, AnUnknownCommandShowsTheHelp) {
    std::string const error = loadError("frames 1\nfrobnicate 3\n");
    EXPECT_NE(error.find(":2: unknown command frobnicate"), std::string::npos) << error;
    EXPECT_NE(error.find(uiScriptHelp()), std::string::npos);
    EXPECT_NE(error.find("  expect-setting KEY NAME"), std::string::npos);
}

TEST(UiScript, TheLightCommandsHelpNamesEveryLightField) {
    auto const line = helpLine("light");
    ASSERT_TRUE(line);
    // The help's FIELD list continues on the next line; take both.
    std::string const help = uiScriptHelp();
    std::string const text = help.substr(help.find(*line), line->size() + 120);
    for (LightField const& f : kLightFields)
        EXPECT_NE(text.find(" " + std::string(f.name) + " "), std::string::npos) << f.name;
}

// The help lists every pipeline field `set` takes, from core/pipeline_fields.h (shading included),
// with what it takes, and names the depth copy's old name.
TEST(UiScript, TheHelpListsEveryPipelineField) {
    std::string const help = uiScriptHelp();
    for (PipelineField const& f : pipelineFields()) {
        EXPECT_TRUE(helpLine(std::string(f.name))) << f.name;
        EXPECT_NE(help.find(fieldValuesText(f)), std::string::npos) << f.name;
    }
    EXPECT_NE(help.find("old name blit"), std::string::npos);
    EXPECT_EQ(loadError("set shading learnopengl\nset blit off\nexpect-setting depth_copy off\n"), "");
}

TEST(UiScript, AnUnsetEnvironmentVariableFailsTheLoad) {
    EXPECT_NE(loadError("open-scene ${GBL_UI_SCRIPT_TEST_SURELY_UNSET}/x.gltf\n")
                  .find("the environment variable GBL_UI_SCRIPT_TEST_SURELY_UNSET is not set"),
              std::string::npos);
}
