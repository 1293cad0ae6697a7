// Autosave timing, run markers and detection of unclean exits.
#include "session/recovery.h"

#include "session/atomic_file.h"
#include "session/config_dir.h"

#include <signal.h>
#include <unistd.h>
#ifdef __EMSCRIPTEN__
#include <emscripten/html5.h>
#endif

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace gbl::ui {

namespace fs = std::filesystem;

Clock steadyClock() {
    return [] { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); };
}

// --- autosave timing ------------------------------------------------------------------------

AutosaveTimer::AutosaveTimer(Clock clock, AutosaveTiming timing) : clock_(std::move(clock)), timing_(timing) {}

void AutosaveTimer::changed() {
    double const now = clock_();
    if (!firstChange_) firstChange_ = now;
    lastChange_ = now;
}

bool AutosaveTimer::due() const {
    if (!firstChange_) return false;
    double const now = clock_();
    return now - lastChange_ >= timing_.quietSeconds || now - *firstChange_ >= timing_.maxSeconds;
}

void AutosaveTimer::saved() {
    firstChange_.reset();
}

void AutosaveTimer::failed() {
    // Keep the change pending; wait a whole quiet period (and a fresh max window) before the
    // next attempt so a full disk is not hammered every frame.
    double const now = clock_();
    firstChange_ = now;
    lastChange_ = now;
}

// --- run markers ----------------------------------------------------------------------------

long editorRunId() {
#ifdef __EMSCRIPTEN__
    static long const id = long(std::fmod(emscripten_date_now(), 2.0e9)) + 1;
    return id;
#else
    return long(::getpid());
#endif
}

bool processAlive(long pid) {
    if (pid <= 0) return false;
#ifdef __EMSCRIPTEN__
    return pid == editorRunId();
#else
    return ::kill(pid_t(pid), 0) == 0 || errno == EPERM;
#endif
}

RecoveryDir::RecoveryDir(std::string dir) : dir_(std::move(dir)) {}

std::string RecoveryDir::markerPath(long pid) const {
    return (fs::path(dir_) / ("running-" + std::to_string(pid))).string();
}

std::string RecoveryDir::sessionPath(long pid) const {
    return (fs::path(dir_) / ("recovery-" + std::to_string(pid) + ".json")).string();
}

std::optional<std::string> RecoveryDir::beginRun(long pid) const {
    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (ec) return "cannot create the recovery directory " + dir_ + ": " + ec.message();
    // A stale session under our pid (a previous process with the same pid) is not ours.
    fs::remove(sessionPath(pid), ec);
    return writeFileAtomically(markerPath(pid), std::to_string(pid) + "\n");
}

void RecoveryDir::endRunCleanly(long pid) const {
    std::error_code ec;
    fs::remove(sessionPath(pid), ec);
    fs::remove(markerPath(pid), ec);
}

void RecoveryDir::forgetSession(long pid) const {
    std::error_code ec;
    fs::remove(sessionPath(pid), ec);
}

std::vector<UncleanExit> RecoveryDir::uncleanExits(ProcessAlive const& alive) const {
    std::vector<UncleanExit> found;
    std::error_code ec;
    for (fs::directory_iterator it(dir_, ec), end; !ec && it != end; it.increment(ec)) {
        std::string const name = it->path().filename().string();
        if (name.rfind("running-", 0) != 0) continue;
        char* stop = nullptr;
        std::string const digits = name.substr(8);
        long const pid = std::strtol(digits.c_str(), &stop, 10);
        if (digits.empty() || *stop != '\0' || pid <= 0 || alive(pid)) continue;
        UncleanExit e;
        e.pid = pid;
        e.markerPath = it->path().string();
        std::error_code fec;
        if (fs::is_regular_file(sessionPath(pid), fec)) {
            e.sessionPath = sessionPath(pid);
            auto const t = fs::last_write_time(e.sessionPath, fec);
            if (!fec) e.modifiedSeconds = std::chrono::duration<double>(t.time_since_epoch()).count();
        }
        found.push_back(e);
    }
    std::sort(found.begin(), found.end(), [](UncleanExit const& a, UncleanExit const& b) {
        if (a.sessionPath.empty() != b.sessionPath.empty()) return !a.sessionPath.empty();
        return a.modifiedSeconds > b.modifiedSeconds;
    });
    return found;
}

void RecoveryDir::discard(UncleanExit const& exit) const {
    std::error_code ec;
    if (!exit.sessionPath.empty()) fs::remove(exit.sessionPath, ec);
    fs::remove(exit.markerPath, ec);
}

double fileClockSeconds() {
    return std::chrono::duration<double>(fs::file_time_type::clock::now().time_since_epoch()).count();
}

std::string ageInWords(double seconds) {
    auto const count = [](long n, char const* unit) {
        return std::to_string(n) + " " + unit + (n == 1 ? "" : "s") + " ago";
    };
    if (seconds < 60.0) return "a moment ago";
    if (seconds < 3600.0) return count(long(seconds / 60.0), "minute");
    if (seconds < 48.0 * 3600.0) return count(long(seconds / 3600.0), "hour");
    return count(long(seconds / 86400.0), "day");
}

std::string defaultRecoveryDir() {
    if (char const* d = std::getenv("GBL_RECOVERY_DIR"); d && *d) return d;
    // Beside imgui.ini in the user's config folder, never in the directory the editor started in.
    return configDir().value_or("/tmp/gbuffer-lab-recovery");
}

}  // namespace gbl::ui
