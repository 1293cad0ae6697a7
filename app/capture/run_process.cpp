// Child processes without a shell: fork, a process group of their own, execvp, and a wait that can stop them.
#include "capture/run_process.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace gbl::capture {

std::optional<std::string> findProgram(std::string const& name) {
    auto executable = [](std::string const& p) {
        struct stat st {};
        return ::stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(p.c_str(), X_OK) == 0;
    };
    if (name.find('/') != std::string::npos) return executable(name) ? std::optional(name) : std::nullopt;
    char const* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "/usr/bin:/bin");
    for (std::string dir; std::getline(dirs, dir, ':');)
        if (!dir.empty() && executable(dir + "/" + name)) return dir + "/" + name;
    return std::nullopt;
}

ProcessResult runProcess(std::vector<std::string> const& argv, ProcessOptions const& o) {
    ProcessResult r;
    std::vector<char*> args;
    for (auto const& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    int errPipe[2];
    if (::pipe2(errPipe, O_CLOEXEC) != 0) {
        r.error = std::strerror(errno);
        return r;
    }
    pid_t const pid = ::fork();
    if (pid < 0) {
        r.error = std::strerror(errno);
        return r;
    }
    if (pid == 0) {
        ::setpgid(0, 0);
        auto redirect = [](std::string const& path, int fd) {
            if (path.empty()) return;
            int const f = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            if (f >= 0) ::dup2(f, fd), ::close(f);
        };
        redirect(o.stdoutPath, 1);
        redirect(o.stderrPath, 2);
        for (auto const& [k, v] : o.env) ::setenv(k.c_str(), v.c_str(), 1);
        ::execvp(args[0], args.data());
        int const e = errno;
        [[maybe_unused]] auto n = ::write(errPipe[1], &e, sizeof e);
        ::_exit(127);
    }
    ::close(errPipe[1]);
    int execErrno = 0;
    bool const failed = ::read(errPipe[0], &execErrno, sizeof execErrno) == sizeof execErrno;
    ::close(errPipe[0]);
    auto const start = std::chrono::steady_clock::now();
    int status = 0;
    for (;;) {
        pid_t const w = ::waitpid(pid, &status, WNOHANG);
        if (w == pid) break;
        double const elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!r.stoppedByUs &&
            ((o.shouldStop && o.shouldStop()) || (o.timeoutSeconds > 0 && elapsed > o.timeoutSeconds))) {
            r.stoppedByUs = true;
            ::kill(-pid, SIGTERM);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(r.stoppedByUs ? 20 : 200));
    }
    if (failed) {
        r.error = std::strerror(execErrno);
        return r;
    }
    r.started = true;
    if (WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
    return r;
}

std::optional<std::string> runForOutput(std::vector<std::string> const& argv, std::string* error,
                                        std::vector<std::pair<std::string, std::string>> const& env) {
    char tmpl[] = "/tmp/gbl_capture_out_XXXXXX";
    int const fd = ::mkstemp(tmpl);
    if (fd < 0) {
        *error = std::strerror(errno);
        return std::nullopt;
    }
    ::close(fd);
    ProcessOptions o;
    o.stdoutPath = tmpl;
    o.stderrPath = std::string(tmpl) + ".err";
    o.env = env;
    ProcessResult const r = runProcess(argv, o);
    std::error_code ec;
    std::string out(std::size_t(std::filesystem::file_size(tmpl, ec)), '\0');
    std::ifstream(tmpl, std::ios::binary).read(out.data(), std::streamsize(out.size()));
    std::ifstream errIn(o.stderrPath);
    std::string lastErr, line;
    while (std::getline(errIn, line))
        if (!line.empty()) lastErr = line;
    std::filesystem::remove(tmpl);
    std::filesystem::remove(o.stderrPath);
    if (!r.started) {
        *error = argv[0] + " could not be started (" + r.error + ")";
        return std::nullopt;
    }
    if (r.exitCode != 0) {
        *error = argv[0] + " failed" + (lastErr.empty() ? std::string() : " (" + lastErr + ")");
        return std::nullopt;
    }
    return out;
}

}  // namespace gbl::capture
