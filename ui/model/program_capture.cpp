// File > Capture a program…: `gbuffer-lab capture` in a child process, watched by a worker thread.
#include "model/program_capture.h"

#include "model/browser_files.h"

#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#ifndef __EMSCRIPTEN__
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
extern char** environ;
#endif

namespace gbl::ui {

namespace fs = std::filesystem;

namespace {

constexpr char const* kLogName = "capture.log";  // the child's stdout and stderr, in its output folder

}  // namespace

CaptureJob::~CaptureJob() {
#ifndef __EMSCRIPTEN__
    if (!done.load() && pid > 0) ::kill(pid, SIGTERM);
#endif
    if (waiter.joinable()) waiter.join();
}

std::optional<std::vector<std::string>> splitCommandLine(std::string const& line, std::string* error) {
    std::vector<std::string> words;
    std::string word;
    bool inWord = false;
    char quote = 0;
    for (std::size_t i = 0; i < line.size(); ++i) {
        char const c = line[i];
        if (quote) {
            if (c == quote)
                quote = 0;
            else if (c == '\\' && quote == '"' && i + 1 < line.size() &&
                     std::string("\"\\$`").find(line[i + 1]) != std::string::npos)
                word += line[++i];
            else
                word += c;
        } else if (c == ' ' || c == '\t' || c == '\n') {
            if (inWord) words.push_back(word), word.clear(), inWord = false;
        } else if (c == '\'' || c == '"') {
            quote = c;
            inWord = true;
        } else if (c == '\\' && i + 1 < line.size()) {
            word += line[++i];
            inWord = true;
        } else {
            word += c;
            inWord = true;
        }
    }
    if (quote) {
        *error = std::string("The command line has an unclosed ") + (quote == '"' ? "double" : "single") + " quote.";
        return std::nullopt;
    }
    if (inWord) words.push_back(word);
    if (words.empty()) {
        *error = "Type the program's command line first (for example ./my_renderer --size 1280x720).";
        return std::nullopt;
    }
    return words;
}

std::vector<std::string> captureArguments(ProgramCaptureState const& s, std::vector<std::string> const& program) {
    std::vector<std::string> args{"capture", "--frame", std::to_string(s.frame), "--out", s.outDir};
    if (s.api != CaptureApi::Auto) args.insert(args.end(), {"--api", s.api == CaptureApi::Egl ? "egl" : "glx"});
    args.push_back("--");
    args.insert(args.end(), program.begin(), program.end());
    return args;
}

std::string captureFailureSentence(std::string const& output, int exitCode) {
    static constexpr std::string_view kPrefix = "gbuffer-lab capture: ";
    std::istringstream lines(output);
    std::string sentence;
    for (std::string l; std::getline(lines, l);)
        if (l.rfind(kPrefix, 0) == 0) sentence = l.substr(kPrefix.size());
    if (!sentence.empty()) {
        sentence[0] = char(std::toupper(static_cast<unsigned char>(sentence[0])));
        if (sentence.back() != '.' && sentence.back() != '?') sentence += '.';
        return sentence;
    }
    return "The capture ended with exit code " + std::to_string(exitCode) + " and no manifest.";
}

bool captureRunning(ProgramCaptureState const& state) {
    return state.job && !state.job->done.load();
}

std::optional<std::string> startProgramCapture(ProgramCaptureState& state, std::string const& self) {
    auto refuse = [&](std::string sentence) -> std::optional<std::string> {
        state.lastError = sentence;
        return sentence;
    };
    if (kInBrowser) return refuse("A page cannot run programs: capture on the desktop with gbuffer-lab capture.");
    if (captureRunning(state)) return refuse("A capture is running already: cancel it first.");
    std::string error;
    auto const program = splitCommandLine(state.commandLine, &error);
    if (!program) return refuse(error);
    if (state.frame < 0) return refuse("The frame must be 0 or more (apitrace counts frames from 0).");
    if (state.outDir.empty()) return refuse("Name a folder for the capture's manifest and images.");
    std::error_code ec;
    fs::create_directories(state.outDir, ec);
    if (!fs::is_directory(state.outDir, ec)) return refuse("The folder " + state.outDir + " cannot be created.");
#ifdef __EMSCRIPTEN__
    (void)self;
    return refuse("A page cannot run programs.");
#else
    std::vector<std::string> argv{self};
    for (auto& a : captureArguments(state, *program)) argv.push_back(a);
    std::vector<char*> args;
    for (auto& a : argv) args.push_back(a.data());
    args.push_back(nullptr);
    std::string const logPath = (fs::path(state.outDir) / kLogName).string();
    posix_spawn_file_actions_t actions;
    ::posix_spawn_file_actions_init(&actions);
    ::posix_spawn_file_actions_addopen(&actions, 1, logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::posix_spawn_file_actions_adddup2(&actions, 1, 2);
    ::posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    pid_t pid = -1;
    int const rc = ::posix_spawn(&pid, self.c_str(), &actions, nullptr, args.data(), environ);
    ::posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) return refuse("The capture could not be started (" + std::string(std::strerror(rc)) + ").");
    auto job = std::make_shared<CaptureJob>();
    job->program = (*program)[0];
    job->outDir = state.outDir;
    job->frame = state.frame;
    job->started = std::chrono::steady_clock::now();
    job->pid = pid;
    CaptureJob* raw = job.get();
    job->waiter = std::thread([raw] {
        int status = 0;
        while (::waitpid(raw->pid, &status, 0) < 0 && errno == EINTR) {
        }
        raw->exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        raw->done.store(true);
    });
    state.job = std::move(job);
    state.lastError.clear();
    return std::nullopt;
#endif
}

void cancelProgramCapture(ProgramCaptureState& state) {
    if (!captureRunning(state)) return;
    state.job->cancelled.store(true);
#ifndef __EMSCRIPTEN__
    ::kill(state.job->pid, SIGTERM);
#endif
}

std::optional<std::string> finishProgramCapture(ProgramCaptureState& state) {
    if (!state.job || !state.job->done.load()) return std::nullopt;
    std::shared_ptr<CaptureJob> const job = std::move(state.job);
    state.job.reset();
    if (job->waiter.joinable()) job->waiter.join();
    fs::path const manifest = fs::path(job->outDir) / "manifest.json";
    std::error_code ec;
    if (job->cancelled.load()) {
        state.lastError = "The capture of " + job->program + " was cancelled.";
        return std::nullopt;
    }
    if (job->exitCode == 0 && fs::is_regular_file(manifest, ec)) {
        state.lastError.clear();
        state.lastManifest = manifest.string();
        state.dialogOpen = false;
        return manifest.string();
    }
    std::ifstream in(fs::path(job->outDir) / kLogName);
    std::stringstream text;
    text << in.rdbuf();
    state.lastError = captureFailureSentence(text.str(), job->exitCode);
    return std::nullopt;
}

}  // namespace gbl::ui
