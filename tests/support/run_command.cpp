// Process helpers for tests that drive the command line.
#include "run_command.h"

#include "test_paths.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace gbl::test {

namespace {
std::string quote(std::string const& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}
}  // namespace

CommandResult runGbufferLab(std::vector<std::string> const& args) {
    std::string cmd = quote(binaryPath());
    for (auto const& a : args) cmd += " " + quote(a);
    cmd += " 2>&1";
    CommandResult r;
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buf{};
    std::size_t n = 0;
    while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), n);
    int const status = pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

CommandResult expectRefused(std::vector<std::string> const& args, std::string const& expect) {
    CommandResult const r = runGbufferLab(args);
    std::string joined;
    for (auto const& a : args) joined += a + " ";
    EXPECT_EQ(r.exitCode, 2) << joined << "\n" << r.output;
    EXPECT_NE(r.output.find(expect), std::string::npos) << joined << "\n" << r.output;
    return r;
}

nlohmann::json readJsonFile(std::string const& path) {
    std::ifstream f(path);
    return nlohmann::json::parse(f);
}

std::string freshTempDir(std::string const& name) {
    namespace fs = std::filesystem;
    fs::path const dir = fs::temp_directory_path() / ("gbl_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir.string();
}

}  // namespace gbl::test
