// UI test script interpreter: reading, checking and dispatching commands through the table.
#include "script/ui_script.h"

#include "script/script_run.h"

#include "core/pipeline_fields.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace gbl::ui {

namespace {

struct CommandGroup {
    char const* title;
    std::span<ScriptCommandSpec const> (*commands)();
};
// The whole command table, in the order the help lists it.
constexpr std::array<CommandGroup, 5> kCommandGroups{{
    {"Editing and waiting", editCommands},
    {"Captures and checks", checkCommands},
    {"Viewer tools, pin and diff (docs/viewers.md)", viewerCommands},
    {"Sessions, undo, recovery and export", sessionCommands},
    {"Scene loading (ui/model/scene_loading.h)", sceneCommands},
}};

ScriptCommandSpec const* findCommand(std::string_view name) {
    for (CommandGroup const& g : kCommandGroups)
        for (ScriptCommandSpec const& c : g.commands())
            if (c.name == name) return &c;
    return nullptr;
}

// Argument words the usage asks for, and whether the last takes the rest of the line.
struct Arguments {
    int count = 0;
    bool restOfLine = false;
};
Arguments arguments(std::string_view usage) {
    Arguments a;
    std::istringstream in{std::string(usage)};
    for (std::string word; in >> word;) {
        ++a.count;
        a.restOfLine = word.size() > 3 && word.ends_with("...");
    }
    return a;
}

// Replaces each ${NAME} in `word` by the environment variable; false (and a sentence) when unset.
bool expandEnvironment(std::string const& word, std::string& out, std::string* error) {
    out.clear();
    for (std::size_t i = 0; i < word.size();) {
        std::size_t const open = word.find("${", i);
        std::size_t const close = open == std::string::npos ? open : word.find('}', open);
        if (close == std::string::npos) {
            out += word.substr(i);
            break;
        }
        std::string const name = word.substr(open + 2, close - open - 2);
        char const* value = std::getenv(name.c_str());
        if (!value) {
            *error = "the environment variable " + name + " is not set";
            return false;
        }
        out += word.substr(i, open - i) + value;
        i = close + 1;
    }
    return true;
}

bool hasSessionSupport(ScriptHost const& host) {
    return host.openSession && host.saveSession && host.undo && host.redo && host.recoveryOffered &&
           host.acceptRecovery;
}

void runCommand(ScriptRun& run, ScriptCommand const& c, ScriptHost& host) {
    ScriptCommandSpec const* spec = findCommand(c.words[0]);  // load() accepted only known names
    if (!spec) return run.check(false, c, "unknown command");
    if (spec->needs == CommandNeeds::Session && !hasSessionSupport(host))
        return run.check(false, c, "this editor build has no session support wired in");
    if (spec->needs == CommandNeeds::SceneLoading && !host.sceneLoading)
        return run.check(false, c, "this editor build cannot load scenes");
    spec->handler(CommandCall{run, host, c, c.words});
}

}  // namespace

double nowSeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string joinWords(std::vector<std::string> const& words, std::size_t from) {
    std::string s;
    for (std::size_t i = from; i < words.size(); ++i) s += (i > from ? " " : "") + words[i];
    return s;
}

float number(std::string const& s) {
    return std::strtof(s.c_str(), nullptr);
}

void ScriptRun::check(bool ok, ScriptCommand const& c, std::string const& detail) {
    std::printf("ui-test %s %s:%d %s%s%s\n", ok ? "PASS" : "FAIL", path.c_str(), c.line, joinWords(c.words, 0).c_str(),
                detail.empty() ? "" : ": ", detail.c_str());
    std::fflush(stdout);
    if (!ok) ++failures;
}

void CommandCall::waitUntil(std::function<bool()> done, double seconds) const {
    run.until = std::move(done);
    run.untilCommand = command;
    run.untilDeadline = nowSeconds() + seconds;
}

std::string uiScriptHelp() {
    std::string out;
    for (CommandGroup const& g : kCommandGroups) {
        out += std::string(g.title) + ":\n";
        for (ScriptCommandSpec const& c : g.commands()) {
            std::string head = "  " + std::string(c.name) + (c.usage.empty() ? "" : " ") + std::string(c.usage);
            head.resize(std::max<std::size_t>(head.size() + 1, 34), ' ');
            std::string help(c.help);
            for (std::size_t at = 0; (at = help.find('\n', at)) != std::string::npos; at += 35)
                help.insert(at + 1, std::string(34, ' '));
            out += head + help + "\n";
        }
    }
    // The fields `set`, `expect-setting` and `b.FIELD` take, from core/pipeline_fields.h.
    out += "Pipeline fields (set FIELD VALUE; B: side B of A/B can change it):\n";
    for (PipelineField const& f : pipelineFields()) {
        std::string head = "  " + std::string(f.name) + (f.sideB ? " B" : "");
        head.resize(std::max<std::size_t>(head.size() + 1, 34), ' ');
        std::string const old = f.oldName.empty() ? "" : "; old name " + std::string(f.oldName);
        out += head + std::string(f.help) + "\n" + std::string(34, ' ') + fieldValuesText(f) + old + "\n";
    }
    return out;
}

UiScript::UiScript() : run_(std::make_unique<ScriptRun>()) {}
UiScript::UiScript(UiScript&&) noexcept = default;
UiScript& UiScript::operator=(UiScript&&) noexcept = default;
UiScript::~UiScript() = default;

bool UiScript::finished() const {
    return run_->next >= run_->commands.size() && run_->wait == 0 && !run_->until;
}
int UiScript::failures() const {
    return run_->failures;
}
bool UiScript::skipped() const {
    return run_->skipped;
}

std::optional<UiScript> UiScript::load(std::string const& path, std::string* error) {
    std::ifstream in(path);
    if (!in) {
        *error = "cannot read UI test script " + path;
        return std::nullopt;
    }
    UiScript script;
    script.run_->path = path;
    std::string line;
    int lineNumber = 0;
    while (std::getline(in, line)) {
        ++lineNumber;
        if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
        std::istringstream words(line);
        ScriptCommand c{lineNumber, {}};
        for (std::string w; words >> w;) {
            std::string expanded;
            if (!expandEnvironment(w, expanded, error)) {
                *error = path + ":" + std::to_string(lineNumber) + ": " + *error;
                return std::nullopt;
            }
            c.words.push_back(std::move(expanded));
        }
        if (c.words.empty()) continue;
        std::string const where = path + ":" + std::to_string(lineNumber) + ": ";
        ScriptCommandSpec const* spec = findCommand(c.words[0]);
        if (!spec) {
            *error = where + "unknown command " + c.words[0] + "\nUI script commands:\n" + uiScriptHelp();
            return std::nullopt;
        }
        Arguments const want = arguments(spec->usage);
        int const given = int(c.words.size()) - 1;
        if (want.restOfLine ? given < want.count : given != want.count) {
            *error = where + "wrong number of arguments for " + c.words[0] + " (usage: " + std::string(spec->name) +
                     (spec->usage.empty() ? "" : " ") + std::string(spec->usage) + ")";
            return std::nullopt;
        }
        script.run_->commands.push_back(std::move(c));
    }
    return script;
}

void UiScript::step(ScriptHost& host) {
    ScriptRun& r = *run_;
    if (r.wait > 0) {
        --r.wait;
        return;
    }
    if (r.until) {
        if (r.until()) {
            r.check(true, *r.untilCommand, "done");
        } else if (nowSeconds() > r.untilDeadline) {
            r.check(false, *r.untilCommand, "timed out");
        } else {
            return;
        }
        r.until = nullptr;
        r.untilCommand.reset();
    }
    while (r.next < r.commands.size() && r.wait == 0 && !r.until) {
        ScriptCommand const& c = r.commands[r.next++];
        runCommand(r, c, host);
    }
}

}  // namespace gbl::ui
