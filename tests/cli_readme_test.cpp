// The README's command list and the program's options agree: every option each command accepts
// (from its --help) is named in the README's "## Commands" blocks for that command, and the README
// names no option the command lacks.
#include "run_command.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

using namespace gbl::test;

namespace {

using OptionSets = std::map<std::string, std::set<std::string>>;  // command ("" = the editor) -> options

std::set<std::string> const kCommands{"", "render", "bench", "lessons", "compare", "check", "capture"};

// The long options a command's --help lists, one per line in its Options section.
std::set<std::string> helpOptions(std::string const& command) {
    std::vector<std::string> args;
    if (!command.empty()) args.push_back(command);
    args.push_back("--help");
    CommandResult const r = runGbufferLab(args);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    std::set<std::string> options;
    std::regex const line(R"(^\s+(?:-\w,)?(--[a-z0-9-]+))");
    std::istringstream in(r.output);
    for (std::string text; std::getline(in, text);) {
        std::smatch m;
        if (std::regex_search(text, m, line) && m[1] != "--help") options.insert(m[1]);
    }
    return options;
}

// The options named in the README's "## Commands" section, per command: the fenced lines that
// start with build/gbuffer-lab, with their indented continuation lines, comments left out.
OptionSets readmeOptions() {
    std::ifstream file(sourcePath("README.md"));
    EXPECT_TRUE(file) << "cannot read README.md";
    OptionSets sets;
    bool inSection = false, inFence = false;
    std::string current;
    bool haveCommand = false;
    std::regex const option(R"(--[a-z0-9-]+)");
    for (std::string text; std::getline(file, text);) {
        if (text.rfind("## ", 0) == 0) inSection = text == "## Commands";
        if (!inSection) continue;
        if (text.rfind("```", 0) == 0) {
            inFence = !inFence;
            haveCommand = false;
            continue;
        }
        if (!inFence) continue;
        text = text.substr(0, text.find('#'));
        std::string const prefix = "build/gbuffer-lab";
        if (text.rfind(prefix, 0) == 0) {
            std::istringstream words(text.substr(prefix.size()));
            std::string first;
            words >> first;
            current = kCommands.count(first) ? first : "";
            haveCommand = true;
        } else if (!haveCommand || text.empty() || text[0] != ' ') {
            continue;
        }
        for (std::sregex_iterator it(text.begin(), text.end(), option), end; it != end; ++it)
            sets[current].insert(it->str());
    }
    return sets;
}

TEST(CliReadme, EveryOptionOfEveryCommandIsListedAndNoOther) {
    OptionSets const readme = readmeOptions();
    for (std::string const& command : kCommands) {
        std::string const name = command.empty() ? "the editor" : command;
        std::set<std::string> const program = helpOptions(command);
        ASSERT_FALSE(program.empty()) << name << ": --help listed no options";
        auto const found = readme.find(command);
        std::set<std::string> const listed = found == readme.end() ? std::set<std::string>{} : found->second;
        for (std::string const& o : program)
            EXPECT_TRUE(listed.count(o)) << "README's Commands lack " << name << "'s " << o;
        for (std::string const& o : listed)
            EXPECT_TRUE(program.count(o))
                << "README's Commands list " << o << " for " << name << ", which it does not accept";
    }
}

// The parser above is not vacuous: it finds options of every command in the README.
TEST(CliReadme, ReadmeListsEachCommand) {
    OptionSets const readme = readmeOptions();
    for (std::string const& command : kCommands)
        EXPECT_FALSE(readme.count(command) == 0 || readme.at(command).empty())
            << "README's Commands name no option of " << (command.empty() ? "the editor" : command);
}

}  // namespace
