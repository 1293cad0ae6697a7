// File > Capture a program's model (issue 49): the command line split as a shell would, the capture's
// arguments, the sentence a failed capture shows, and a real child process that fails and one that is
// refused before it starts. ui_capture.sh drives the dialog itself with real input.
#include "model/program_capture.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

using namespace gbl::ui;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> split(std::string const& line) {
    std::string error;
    auto const words = splitCommandLine(line, &error);
    EXPECT_TRUE(words.has_value()) << error;
    return words.value_or(std::vector<std::string>{});
}

}  // namespace

TEST(ProgramCapture, SplitsLikeAShell) {
    EXPECT_EQ(split("./demo --size 320x180"), (std::vector<std::string>{"./demo", "--size", "320x180"}));
    EXPECT_EQ(split("  a\t b  "), (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(split("'/my dir/demo' \"two words\" x\\ y"),
              (std::vector<std::string>{"/my dir/demo", "two words", "x y"}));
    EXPECT_EQ(split("say \"a \\\"quote\\\"\" 'no \\escape'"),
              (std::vector<std::string>{"say", "a \"quote\"", "no \\escape"}));
    EXPECT_EQ(split("empty '' arg"), (std::vector<std::string>{"empty", "", "arg"}));
}

TEST(ProgramCapture, RefusesBadCommandLinesInOneSentence) {
    std::string error;
    EXPECT_FALSE(splitCommandLine("./demo 'open", &error));
    EXPECT_EQ(error, "The command line has an unclosed single quote.");
    EXPECT_FALSE(splitCommandLine("   ", &error));
    EXPECT_EQ(error.rfind("Type the program's command line first", 0), 0u) << error;
}

TEST(ProgramCapture, Arguments) {
    ProgramCaptureState s;
    s.frame = 3;
    s.outDir = "/tmp/out";
    EXPECT_EQ(captureArguments(s, {"./demo", "-x"}),
              (std::vector<std::string>{"capture", "--frame", "3", "--out", "/tmp/out", "--", "./demo", "-x"}));
    s.api = CaptureApi::Egl;
    EXPECT_EQ(captureArguments(s, {"d"}),
              (std::vector<std::string>{"capture", "--frame", "3", "--out", "/tmp/out", "--api", "egl", "--", "d"}));
    s.api = CaptureApi::Glx;
    EXPECT_EQ(captureArguments(s, {"d"})[6], "glx");
}

TEST(ProgramCapture, FailureSentence) {
    EXPECT_EQ(captureFailureSentence(
                  "noise\ngbuffer-lab capture: this frame has no G-buffer: is it a forward renderer?\n", 2),
              "This frame has no G-buffer: is it a forward renderer?");
    EXPECT_EQ(captureFailureSentence("gbuffer-lab capture: x is not a program that can be run\n", 2),
              "X is not a program that can be run.");
    EXPECT_EQ(captureFailureSentence("Segmentation fault\n", -1),
              "The capture ended with exit code -1 and no manifest.");
}

// A real child: /bin/false stands in for gbuffer-lab (it fails with no sentence), /bin/true ends well
// but writes no manifest; both are refused in one sentence and nothing opens.
TEST(ProgramCapture, ChildProcessOutcomes) {
    fs::path const dir = fs::temp_directory_path() / ("gbl_program_capture_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    ProgramCaptureState s;
    s.commandLine = "./demo";
    s.outDir = dir.string();
    for (char const* self : {"/bin/false", "/bin/true"}) {
        ASSERT_EQ(startProgramCapture(s, self), std::nullopt) << s.lastError;
        EXPECT_TRUE(fs::is_directory(dir));
        auto const start = std::chrono::steady_clock::now();
        while (captureRunning(s) && std::chrono::steady_clock::now() - start < std::chrono::seconds(20))
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        EXPECT_EQ(finishProgramCapture(s), std::nullopt);
        EXPECT_EQ(s.lastError, std::string(self) == "/bin/false"
                                   ? "The capture ended with exit code 1 and no manifest."
                                   : "The capture ended with exit code 0 and no manifest.");
        EXPECT_FALSE(s.job);
    }
    // Refused before anything starts: an empty command line, and no folder.
    s.commandLine = "";
    EXPECT_NE(startProgramCapture(s, "/bin/true"), std::nullopt);
    EXPECT_FALSE(s.job);
    s.commandLine = "./demo";
    s.outDir = "";
    EXPECT_EQ(startProgramCapture(s, "/bin/true"), "Name a folder for the capture's manifest and images.");
    // The spawn itself failing.
    s.outDir = dir.string();
    auto const why = startProgramCapture(s, (dir / "no_such_gbuffer_lab").string());
    ASSERT_TRUE(why.has_value());
    EXPECT_EQ(why->rfind("The capture could not be started (", 0), 0u) << *why;
    fs::remove_all(dir);
}

// A capture still running when the editor closes is stopped, not waited out.
TEST(ProgramCapture, DestroyingAJobStopsItsChild) {
    fs::path const dir = fs::temp_directory_path() / ("gbl_program_capture_stop_" + std::to_string(::getpid()));
    ProgramCaptureState s;
    s.commandLine = "./demo";
    s.outDir = dir.string();
    // /bin/sleep takes "capture --frame ..." as bad arguments and exits at once; a shell script that
    // sleeps stands in for a long capture.
    fs::create_directories(dir);
    fs::path const slow = dir / "slow.sh";
    {
        std::FILE* f = std::fopen(slow.c_str(), "w");
        ASSERT_NE(f, nullptr);
        std::fputs("#!/bin/sh\nexec sleep 30\n", f);
        std::fclose(f);
    }
    fs::permissions(slow, fs::perms::owner_all);
    ASSERT_EQ(startProgramCapture(s, slow.string()), std::nullopt) << s.lastError;
    EXPECT_TRUE(captureRunning(s));
    auto const start = std::chrono::steady_clock::now();
    s.job.reset();
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
    // Cancel on a running one: the sentence says so.
    ASSERT_EQ(startProgramCapture(s, slow.string()), std::nullopt);
    cancelProgramCapture(s);
    while (captureRunning(s)) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    EXPECT_EQ(finishProgramCapture(s), std::nullopt);
    EXPECT_EQ(s.lastError, "The capture of ./demo was cancelled.");
    fs::remove_all(dir);
}
