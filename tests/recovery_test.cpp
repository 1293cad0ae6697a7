// Recovery: autosave timing on a fake clock, run markers, and unclean-exit detection with a real SIGKILL.
#include "session/recovery.h"
#include "run_command.h"
#include "session/atomic_file.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>

using namespace gbl::ui;
namespace fs = std::filesystem;
namespace test = gbl::test;

namespace {

struct FakeClock {
    double now = 100.0;
    Clock clock() {
        return [this] { return now; };
    }
};

}  // namespace

// --- autosave timing ------------------------------------------------------------------------

TEST(Autosave, NothingChangedNothingDue) {
    FakeClock t;
    AutosaveTimer a(t.clock());
    for (int i = 0; i < 100; ++i, t.now += 1.0) EXPECT_FALSE(a.due());
    EXPECT_FALSE(a.pending());
}

TEST(Autosave, DueAQuietPeriodAfterTheLastChange) {
    FakeClock t;
    AutosaveTimer a(t.clock(), {3.0, 20.0});
    a.changed();
    EXPECT_TRUE(a.pending());
    t.now += 2.9;
    EXPECT_FALSE(a.due());
    t.now += 0.1;
    EXPECT_TRUE(a.due());
    a.saved();
    EXPECT_FALSE(a.due());
    EXPECT_FALSE(a.pending());
    t.now += 60.0;
    EXPECT_FALSE(a.due());
}

TEST(Autosave, EachChangeRestartsTheQuietPeriod) {
    FakeClock t;
    AutosaveTimer a(t.clock(), {3.0, 20.0});
    a.changed();
    t.now += 2.0;
    a.changed();
    t.now += 2.0;  // 4 s after the first change, 2 s after the last
    EXPECT_FALSE(a.due());
    t.now += 1.0;
    EXPECT_TRUE(a.due());
}

TEST(Autosave, ContinuousChangesAreSavedByTheMaximumDelay) {
    FakeClock t;
    AutosaveTimer a(t.clock(), {3.0, 20.0});
    // A change every half second (a long drag): the quiet period never comes.
    for (int i = 0; i < 39; ++i) {
        a.changed();
        EXPECT_FALSE(a.due()) << t.now;
        t.now += 0.5;
    }
    a.changed();  // 19.5 s after the first
    t.now += 0.5;
    EXPECT_TRUE(a.due());  // 20 s after the first unsaved change
}

TEST(Autosave, AFailedSaveRetriesAfterAnotherQuietPeriod) {
    FakeClock t;
    AutosaveTimer a(t.clock(), {3.0, 20.0});
    a.changed();
    t.now += 3.0;
    ASSERT_TRUE(a.due());
    a.failed();
    EXPECT_TRUE(a.pending());
    EXPECT_FALSE(a.due());  // not again in the very next frame
    t.now += 3.0;
    EXPECT_TRUE(a.due());
}

// --- markers and unclean exits ---------------------------------------------------------------

TEST(Recovery, CleanRunLeavesNothing) {
    RecoveryDir const r(test::freshTempDir("recovery_clean"));
    ASSERT_EQ(r.beginRun(4242), std::nullopt);
    EXPECT_TRUE(fs::exists(r.markerPath(4242)));
    ASSERT_EQ(writeFileAtomically(r.sessionPath(4242), "{}"), std::nullopt);
    r.endRunCleanly(4242);
    EXPECT_FALSE(fs::exists(r.markerPath(4242)));
    EXPECT_FALSE(fs::exists(r.sessionPath(4242)));
    EXPECT_TRUE(r.uncleanExits([](long) { return false; }).empty());
}

TEST(Recovery, DeadProcessWithMarkerIsAnUncleanExit) {
    RecoveryDir const r(test::freshTempDir("recovery_dead"));
    ASSERT_EQ(r.beginRun(4243), std::nullopt);
    ASSERT_EQ(writeFileAtomically(r.sessionPath(4243), "{\"x\": 1}"), std::nullopt);
    // While the process lives it is another editor, not a crash.
    EXPECT_TRUE(r.uncleanExits([](long) { return true; }).empty());
    auto const found = r.uncleanExits([](long) { return false; });
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].pid, 4243);
    EXPECT_EQ(found[0].sessionPath, r.sessionPath(4243));
    r.discard(found[0]);
    EXPECT_TRUE(r.uncleanExits([](long) { return false; }).empty());
    EXPECT_FALSE(fs::exists(r.sessionPath(4243)));
}

TEST(Recovery, CrashBeforeTheFirstAutosaveHasNothingToOffer) {
    RecoveryDir const r(test::freshTempDir("recovery_nosave"));
    ASSERT_EQ(r.beginRun(77), std::nullopt);
    auto const found = r.uncleanExits([](long) { return false; });
    ASSERT_EQ(found.size(), 1u);
    EXPECT_TRUE(found[0].sessionPath.empty());
}

TEST(Recovery, NewestRecoveryFirstAndStrangeNamesIgnored) {
    std::string const dir = test::freshTempDir("recovery_order");
    RecoveryDir const r(dir);
    for (long pid : {11L, 12L, 13L}) ASSERT_EQ(r.beginRun(pid), std::nullopt);
    ASSERT_EQ(writeFileAtomically(r.sessionPath(11), "{}"), std::nullopt);
    ASSERT_EQ(writeFileAtomically(r.sessionPath(12), "{}"), std::nullopt);
    fs::last_write_time(r.sessionPath(11), fs::file_time_type::clock::now() - std::chrono::hours(1));
    ASSERT_EQ(writeFileAtomically(dir + "/running-abc", ""), std::nullopt);
    ASSERT_EQ(writeFileAtomically(dir + "/running-", ""), std::nullopt);
    ASSERT_EQ(writeFileAtomically(dir + "/running--5", ""), std::nullopt);
    auto const found = r.uncleanExits([](long pid) { return pid == 13; });
    ASSERT_EQ(found.size(), 2u);
    EXPECT_EQ(found[0].pid, 12);  // the newer session
    EXPECT_EQ(found[1].pid, 11);
}

TEST(Recovery, MissingDirectoryMeansNoUncleanExits) {
    RecoveryDir const r(test::freshTempDir("recovery_missing") + "/not/there");
    EXPECT_TRUE(r.uncleanExits().empty());
}

TEST(Recovery, UnwritableDirectoryIsAMessage) {
    RecoveryDir const r("/proc/gbuffer-lab-recovery");
    auto const err = r.beginRun(1);
    ASSERT_TRUE(err);
    EXPECT_NE(err->find("/proc/gbuffer-lab-recovery"), std::string::npos) << *err;
}

TEST(Recovery, ProcessKilledWithSigkillIsDetected) {
    // A real process marks its run, autosaves, and is killed with SIGKILL: nothing of its own
    // clean-up runs. The next start must find its session.
    RecoveryDir const r(test::freshTempDir("recovery_sigkill"));
    int ready[2];
    ASSERT_EQ(::pipe(ready), 0);
    pid_t const child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        long const me = long(::getpid());
        bool const ok = !r.beginRun(me) && !writeFileAtomically(r.sessionPath(me), "{\"autosaved\": true}");
        char const c = ok ? 'y' : 'n';
        (void)!::write(ready[1], &c, 1);
        for (;;) ::pause();  // waits for the kill
    }
    ::close(ready[1]);
    char c = 0;
    ASSERT_EQ(::read(ready[0], &c, 1), 1);
    ::close(ready[0]);
    ASSERT_EQ(c, 'y');
    // Alive: another editor, not offered.
    EXPECT_TRUE(r.uncleanExits().empty());
    ::kill(child, SIGKILL);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status));
    auto const found = r.uncleanExits();
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].pid, long(child));
    std::string error;
    EXPECT_EQ(readWholeFile(found[0].sessionPath, &error).value_or(error), "{\"autosaved\": true}");
}

TEST(Recovery, DirectoryComesFromTheEnvironment) {
    ::setenv("GBL_RECOVERY_DIR", "/tmp/somewhere-else", 1);
    EXPECT_EQ(defaultRecoveryDir(), "/tmp/somewhere-else");
    ::unsetenv("GBL_RECOVERY_DIR");
    ::setenv("XDG_CONFIG_HOME", "/tmp/config", 1);
    EXPECT_EQ(defaultRecoveryDir(), "/tmp/config/gbuffer-lab");
    ::unsetenv("XDG_CONFIG_HOME");
}
