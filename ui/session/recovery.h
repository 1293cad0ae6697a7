// Crash recovery: when to autosave (pure timing over an injectable clock), a marker file per
// running editor, and finding the sessions that editors which did not exit cleanly left behind.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace gbl::ui {

// Seconds on any monotonic clock; tests pass a fake one.
using Clock = std::function<double()>;
Clock steadyClock();

struct AutosaveTiming {
    double quietSeconds = 3.0;  // save this long after the last change...
    double maxSeconds = 20.0;   // ...but no later than this after the first unsaved change,
                                // so an hour of continuous dragging is not all at risk
};

// Decides when the recovery file is written. The editor calls changed() when the session
// state differs from what was last saved, asks due() each frame, and calls saved() after
// writing (or failed() when the write failed, to retry after another quiet period).
class AutosaveTimer {
public:
    explicit AutosaveTimer(Clock clock, AutosaveTiming timing = {});

    void changed();
    bool due() const;
    void saved();
    void failed();
    bool pending() const { return firstChange_.has_value(); }

private:
    Clock clock_;
    AutosaveTiming timing_;
    std::optional<double> firstChange_;  // first change not in the recovery file yet
    double lastChange_ = 0.0;
};

// A previous editor that ended without a clean exit (killed, crashed, power cut).
struct UncleanExit {
    long pid = 0;
    std::string markerPath;
    std::string sessionPath;       // its recovery session; empty when it never autosaved
    double modifiedSeconds = 0.0;  // recovery file age key (seconds since epoch), newest first
};

using ProcessAlive = std::function<bool(long pid)>;
bool processAlive(long pid);  // kill(pid, 0): the pid exists (possibly owned by another user)

// The id of this editor's run markers: its process id. In the browser every page's process id is
// the same number, so a page takes one of its own (its start time in milliseconds), and
// processAlive is true there for that id alone: a page that went (a reload, a closed tab) left
// an unclean exit to offer, as a crashed desktop editor does.
long editorRunId();

// One directory holds a marker "running-<pid>" per live editor and its recovery session
// "recovery-<pid>.json". Per-pid names let two editors run side by side without taking each
// other's recovery for a crash.
class RecoveryDir {
public:
    explicit RecoveryDir(std::string dir);
    std::string const& dir() const { return dir_; }

    std::string markerPath(long pid) const;
    std::string sessionPath(long pid) const;

    // Creates the directory and this run's marker. Error sentence on failure (the editor then
    // runs without recovery and says so).
    std::optional<std::string> beginRun(long pid) const;
    // Removes this run's marker and recovery session: the clean-exit path.
    void endRunCleanly(long pid) const;
    // Removes this run's recovery session and keeps its marker: nothing unsaved is left to offer
    // (the edits were saved or undone).
    void forgetSession(long pid) const;

    // Markers whose process is gone, newest recovery session first. Markers of live processes
    // (another editor) are left alone.
    std::vector<UncleanExit> uncleanExits(ProcessAlive const& alive = processAlive) const;
    // Forgets an unclean exit once its session was restored or declined.
    void discard(UncleanExit const& exit) const;

private:
    std::string dir_;
};

// Now on the clock of UncleanExit::modifiedSeconds (the file system's).
double fileClockSeconds();

// How long ago, in the words a student reads: "a moment ago", "1 minute ago", "3 minutes ago",
// "2 hours ago", "3 days ago".
std::string ageInWords(double seconds);

// $GBL_RECOVERY_DIR, else the config folder (session/config_dir.h: $XDG_CONFIG_HOME/gbuffer-lab,
// else ~/.config/gbuffer-lab), else /tmp/gbuffer-lab-recovery.
std::string defaultRecoveryDir();

}  // namespace gbl::ui
