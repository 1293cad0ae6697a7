// File > Capture a program… (issue 49): the editor runs `gbuffer-lab capture` on a command line the user
// types, in a child process watched by a worker thread so the window keeps drawing, and opens the
// manifest it writes as File > Open G-buffer does. Desktop only: the browser build has no processes.
// No ImGui, no GL.
#pragma once

#include <glm/glm.hpp>

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace gbl::ui {

// What the traced program draws through (`capture --api`).
enum class CaptureApi { Auto, Egl, Glx };

// A capture running in a child process. Its destructor stops the child (SIGTERM, which `capture`
// passes on to the traced program) and waits for it, so closing the editor leaves nothing running.
struct CaptureJob {
    std::string program;  // the command line's first word, for the progress line
    std::string outDir;
    int frame = 0;
    std::chrono::steady_clock::time_point started;
    int pid = -1;
    std::atomic<bool> done{false};
    std::atomic<bool> cancelled{false};
    int exitCode = -1;  // set before done
    std::thread waiter;
    ~CaptureJob();
};

struct ProgramCaptureState {
    bool dialogOpen = false;
    bool focusCommand = false;  // the command field takes the keyboard when the dialog opens
    std::string commandLine;    // PROGRAM [ARGS...], split as a shell would (quotes, backslashes)
    int frame = 1;              // `capture`'s default: frame 0 often only uploads
    std::string outDir;         // prefilled with ./capture (the command's default) made absolute
    CaptureApi api = CaptureApi::Auto;
    std::shared_ptr<CaptureJob> job;
    std::string lastError;  // one sentence ("" after a good capture or a new start)
    std::string lastManifest;
    // Rectangles for the frame log (0 unless drawn): File's item and the dialog's fields.
    glm::vec4 menuItemRect{0.0f};
    glm::vec4 commandRect{0.0f};
    glm::vec4 frameRect{0.0f};
    glm::vec4 outRect{0.0f};
    glm::vec4 eglRect{0.0f};
    glm::vec4 captureButtonRect{0.0f};
};

// Splits a command line into words as a POSIX shell would for a plain command (no variables, globs or
// operators): blanks separate, '…' and "…" quote, a backslash escapes. nullopt and *error on an
// unclosed quote or no words.
std::optional<std::vector<std::string>> splitCommandLine(std::string const& line, std::string* error);

// The `gbuffer-lab capture` argument list (after the executable) for the dialog's values.
std::vector<std::string> captureArguments(ProgramCaptureState const& state, std::vector<std::string> const& program);

// Starts `self capture …` with the dialog's values: nullopt, or why not in one sentence (also kept in
// lastError). Refused while a capture runs and in the browser.
std::optional<std::string> startProgramCapture(ProgramCaptureState& state, std::string const& self);
void cancelProgramCapture(ProgramCaptureState& state);
bool captureRunning(ProgramCaptureState const& state);

// Once per frame: a finished capture gives the manifest to open (the dialog closes) or sets lastError
// to the command's own sentence. Returns the manifest's path on success.
std::optional<std::string> finishProgramCapture(ProgramCaptureState& state);

// The sentence a failed `capture` printed ("gbuffer-lab capture: WHY" in its output), else a general one.
std::string captureFailureSentence(std::string const& output, int exitCode);

}  // namespace gbl::ui
