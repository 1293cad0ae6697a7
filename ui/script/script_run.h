// The UI script's interpreter state and its command table, shared by the files that implement
// the commands (ui/script/script_*_commands.cpp, ui_script_scene.cpp). Not for use elsewhere.
#pragma once

#include "script/ui_script.h"

#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gbl::ui {

struct ScriptCommand {
    int line = 0;
    std::vector<std::string> words;  // words[0] is the command's name
};

struct ScriptRun {
    std::string path;
    std::vector<ScriptCommand> commands;
    std::size_t next = 0;  // the next command to run
    int wait = 0;          // frames left before it runs
    int failures = 0;
    bool skipped = false;  // skip-unless-exists ended the script
    std::map<std::string, FloatImage> captures;
    // A command that waits for a condition (wait-autosave, wait-log, ...): checked once per
    // frame until it holds or the deadline passes.
    std::function<bool()> until;
    std::optional<ScriptCommand> untilCommand;
    double untilDeadline = 0.0;
    std::map<std::string, std::string> brokenShaders;  // file -> original text
    long baselineObjects = -1;
    double baselineRssMb = 0.0;

    // Prints "ui-test PASS|FAIL file:line command: detail" and counts failures.
    void check(bool ok, ScriptCommand const& c, std::string const& detail);
};

// What a command's handler gets: the interpreter, the editor and the command's words.
struct CommandCall {
    ScriptRun& run;
    ScriptHost& host;
    ScriptCommand const& command;
    std::vector<std::string> const& w;  // command.words

    void check(bool ok, std::string const& detail = {}) const { run.check(ok, command, detail); }
    // Runs frames until done() holds (a PASS) or `seconds` pass (a FAIL).
    void waitUntil(std::function<bool()> done, double seconds) const;
};

// Host support a command needs; without it the command fails (never crashes).
enum class CommandNeeds { Nothing, Session, SceneLoading };

struct ScriptCommandSpec {
    std::string_view name;
    // The argument words, as the help shows them. A last word ending in "..." takes the rest of
    // the line (at least one word); otherwise the count of words is the exact argument count.
    std::string_view usage;
    std::string_view help;  // lines after the first start with '\n'
    void (*handler)(CommandCall const&);
    CommandNeeds needs = CommandNeeds::Nothing;
};

// The command table, one group per file that implements it; uiScriptHelp() and the dispatch
// in ui_script.cpp walk these, so a command is named, checked, run and documented in one row.
std::span<ScriptCommandSpec const> editCommands();     // script_edit_commands.cpp
std::span<ScriptCommandSpec const> checkCommands();    // script_check_commands.cpp
std::span<ScriptCommandSpec const> sessionCommands();  // script_session_commands.cpp
std::span<ScriptCommandSpec const> sceneCommands();    // ui_script_scene.cpp
std::span<ScriptCommandSpec const> viewerCommands();   // script_viewer_commands.cpp

// Helpers the command files share (ui_script.cpp).
double nowSeconds();
std::string joinWords(std::vector<std::string> const& words, std::size_t from);
// strtof: accepts "nan" and "inf", which scripts use to test that bad input is refused.
float number(std::string const& s);

}  // namespace gbl::ui
