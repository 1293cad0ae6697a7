// The editor's session life cycle without a window: autosave timing on a fake clock, the
// recovery offer after an unclean exit, all-or-nothing opening, undo through the controller.
#include "editor/session_controller.h"
#include "model/gbuffer_opening.h"
#include "run_command.h"
#include "session/atomic_file.h"
#include "session/editor_session.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>

using namespace gbl;
using namespace gbl::ui;
namespace fs = std::filesystem;
namespace test = gbl::test;

namespace {

struct Fixture {
    double now = 1000.0;
    std::string dir;
    EditorState state;
    std::vector<std::string> loads;  // scenes the loader was asked for
    bool loaderFails = false;

    explicit Fixture(std::string const& name) : dir(test::freshTempDir(name)) {
        state.sceneSource = "default";
        state.lights.resize(4);
    }
    Clock clock() {
        return [this] { return now; };
    }
    SceneLoader loader() {
        return [this](std::string const& scene, int) -> std::optional<std::string> {
            loads.push_back(scene);
            if (loaderFails) return std::string("cannot open " + scene);
            state.sceneSource = scene;
            return std::nullopt;
        };
    }
    // Runs frames for `seconds` at 20 frames per second.
    void run(SessionController& c, double seconds, bool editing = false) {
        for (double t = 0.0; t < seconds; t += 0.05) {
            now += 0.05;
            c.afterFrame(state, editing);
        }
    }
};

long deadPid() {
    pid_t const p = ::fork();
    if (p == 0) ::_exit(0);
    ::waitpid(p, nullptr, 0);
    return long(p);
}

}  // namespace

TEST(SessionController, AutosavesAQuietPeriodAfterAChange) {
    Fixture f("controller_autosave");
    SessionController c(f.clock(), RecoveryDir(f.dir), 5000, {3.0, 20.0});
    c.start(f.state, 32);
    EXPECT_TRUE(fs::exists(RecoveryDir(f.dir).markerPath(5000)));
    f.run(c, 10.0);
    EXPECT_EQ(c.autosaves(), 0);  // nothing changed, nothing written
    EXPECT_FALSE(fs::exists(c.recoveryPath()));

    f.state.lights[2].intensity = 6.5f;
    f.run(c, 2.0);
    EXPECT_EQ(c.autosaves(), 0);  // still within the quiet period
    f.run(c, 2.0);
    EXPECT_EQ(c.autosaves(), 1);
    SessionLoad const saved = loadSession(c.recoveryPath());
    ASSERT_TRUE(saved.session) << saved.error;
    EXPECT_EQ(saved.session->lights[2].intensity, 6.5f);

    f.run(c, 10.0);
    EXPECT_EQ(c.autosaves(), 1);  // no change since: no rewrite
    c.endCleanly();
    EXPECT_TRUE(fs::is_empty(f.dir));
}

TEST(SessionController, OffersTheSessionOfAnEditorThatDidNotExitCleanly) {
    Fixture f("controller_offer");
    RecoveryDir const dir(f.dir);
    long const crashed = deadPid();
    ASSERT_EQ(dir.beginRun(crashed), std::nullopt);
    Session lost = captureSession(f.state, 32);
    lost.lights.resize(9);
    lost.lights[8].kq = 0.125f;
    lost.pipeline.cull = CullMode::Back;
    ASSERT_EQ(saveSession(dir.sessionPath(crashed), lost), std::nullopt);

    SessionController c(f.clock(), dir, 5001);
    c.start(f.state, 32);
    ASSERT_TRUE(c.panel.recoveryOffer);
    EXPECT_EQ(c.panel.recoveryOffer->pid, crashed);
    EXPECT_NE(c.panel.recoveryWhy.find("9 lights"), std::string::npos) << c.panel.recoveryWhy;

    ASSERT_EQ(c.restoreRecovery(f.state, f.loader()), std::nullopt);
    EXPECT_EQ(f.state.lights.size(), 9u);
    EXPECT_EQ(f.state.lights[8].kq, 0.125f);
    EXPECT_EQ(f.state.pipeline.cull, CullMode::Back);
    EXPECT_TRUE(f.loads.empty());  // same scene: not reloaded
    EXPECT_FALSE(c.panel.recoveryOffer);
    EXPECT_FALSE(fs::exists(dir.markerPath(crashed)));
    EXPECT_FALSE(fs::exists(dir.sessionPath(crashed)));
    // The restored state becomes this run's autosave soon, so a second crash loses nothing.
    f.run(c, 4.0);
    EXPECT_GE(c.autosaves(), 1);
    ASSERT_TRUE(loadSession(c.recoveryPath()).session);
    EXPECT_EQ(loadSession(c.recoveryPath()).session->lights.size(), 9u);
}

TEST(SessionController, DecliningForgetsTheCrash) {
    Fixture f("controller_decline");
    RecoveryDir const dir(f.dir);
    long const crashed = deadPid();
    ASSERT_EQ(dir.beginRun(crashed), std::nullopt);
    ASSERT_EQ(saveSession(dir.sessionPath(crashed), captureSession(f.state, 32)), std::nullopt);
    SessionController c(f.clock(), dir, 5002);
    c.start(f.state, 32);
    ASSERT_TRUE(c.panel.recoveryOffer);
    c.discardRecovery();
    EXPECT_FALSE(c.panel.recoveryOffer);
    SessionController again(f.clock(), dir, 5003);
    again.start(f.state, 32);
    EXPECT_FALSE(again.panel.recoveryOffer);
}

TEST(SessionController, OpeningABadSessionChangesNothing) {
    Fixture f("controller_bad");
    SessionController c(f.clock(), std::nullopt, 5004);
    c.start(f.state, 32);
    Session s = captureSession(f.state, 32);
    s.lights.resize(2);
    std::string const good = f.dir + "/good.json";
    ASSERT_EQ(saveSession(good, s), std::nullopt);
    std::string text = sessionToJson(s);
    text.replace(text.find("\"kq\""), 4, "\"kk\"");
    std::string const bad = f.dir + "/bad.json";
    ASSERT_EQ(writeFileAtomically(bad, text), std::nullopt);

    auto const err = c.openSession(bad, f.state, f.loader());
    ASSERT_TRUE(err);
    EXPECT_NE(err->find("lights[0].kk is not a known field"), std::string::npos) << *err;
    EXPECT_EQ(f.state.lights.size(), 4u);
    EXPECT_EQ(c.panel.currentPath, "");

    ASSERT_EQ(c.openSession(good, f.state, f.loader()), std::nullopt);
    EXPECT_EQ(f.state.lights.size(), 2u);
    EXPECT_EQ(c.panel.currentPath, good);
}

TEST(SessionController, ASceneThatFailsToLoadLeavesTheStateAsItWas) {
    Fixture f("controller_scene");
    SessionController c(f.clock(), std::nullopt, 5005);
    c.start(f.state, 32);
    Session s = captureSession(f.state, 32);
    s.scene = "/nowhere/model.glb";
    s.lights.resize(1);
    std::string const path = f.dir + "/other.json";
    ASSERT_EQ(saveSession(path, s), std::nullopt);
    f.loaderFails = true;
    auto const err = c.openSession(path, f.state, f.loader());
    ASSERT_TRUE(err);
    EXPECT_NE(err->find("cannot open /nowhere/model.glb"), std::string::npos) << *err;
    EXPECT_EQ(f.state.lights.size(), 4u);
    EXPECT_EQ(f.state.sceneSource, "default");
    f.loaderFails = false;
    ASSERT_EQ(c.openSession(path, f.state, f.loader()), std::nullopt);
    EXPECT_EQ(f.loads.back(), "/nowhere/model.glb");
    EXPECT_EQ(f.state.lights.size(), 1u);
}

// A session of the default scene with its glass panes (default_scene_glass, issue 47) asks the loader
// for "default+glass"; one without them for "default"; the editor's session keeps the panes.
TEST(SessionController, TheGlassOfASessionReachesTheSceneLoader) {
    Fixture f("controller_glass");
    SessionController c(f.clock(), std::nullopt, 5013);
    c.start(f.state, 32);
    SceneLoader const load = [&f](std::string const& scene, int) -> std::optional<std::string> {
        f.loads.push_back(scene);
        f.state.sceneSource = scene == kDefaultSceneGlass ? "default" : scene;
        f.state.sceneGlass = scene == kDefaultSceneGlass;
        return std::nullopt;
    };
    Session s = captureSession(f.state, 32);
    EXPECT_FALSE(s.defaultSceneGlass);
    s.defaultSceneGlass = true;
    std::string const glass = f.dir + "/glass.json";
    ASSERT_EQ(saveSession(glass, s), std::nullopt);
    ASSERT_EQ(c.openSession(glass, f.state, load), std::nullopt);
    ASSERT_EQ(f.loads.size(), 1u);
    EXPECT_EQ(f.loads.back(), "default+glass");
    EXPECT_EQ(f.state.sceneName(), "default+glass");
    EXPECT_TRUE(captureSession(f.state, 32).defaultSceneGlass);
    ASSERT_EQ(c.openSession(glass, f.state, load), std::nullopt);
    EXPECT_EQ(f.loads.size(), 1u);  // the same scene: not loaded again
    s.defaultSceneGlass = false;
    std::string const plain = f.dir + "/plain.json";
    ASSERT_EQ(saveSession(plain, s), std::nullopt);
    ASSERT_EQ(c.openSession(plain, f.state, load), std::nullopt);
    EXPECT_EQ(f.loads.back(), "default");
    EXPECT_FALSE(f.state.sceneGlass);
}

TEST(SessionController, UndoAndRedoThroughTheController) {
    Fixture f("controller_undo");
    SessionController c(f.clock(), std::nullopt, 5006);
    c.start(f.state, 32);
    f.state.lights[0].position.y = 3.0f;
    f.run(c, 0.2, true);  // dragging
    f.state.lights[0].position.y = 4.0f;
    f.run(c, 0.2, false);  // released
    f.state.pipeline.mode = LightingMode::Forward;
    f.run(c, 1.0);
    c.undo(f.state);
    EXPECT_EQ(f.state.pipeline.mode, LightingMode::Quad);
    EXPECT_EQ(f.state.lights[0].position.y, 4.0f);
    c.undo(f.state);
    EXPECT_EQ(f.state.lights[0].position.y, 0.0f);  // the whole drag at once
    c.redo(f.state);
    EXPECT_EQ(f.state.lights[0].position.y, 4.0f);
    // Opening a session starts a fresh history.
    std::string const path = f.dir + "/s.json";
    ASSERT_EQ(c.saveSession(path, f.state), std::nullopt);
    ASSERT_EQ(c.openSession(path, f.state, f.loader()), std::nullopt);
    EXPECT_FALSE(c.history().canUndo());
}

TEST(SessionController, UnwritableRecoveryDirectoryTurnsRecoveryOffWithAMessage) {
    Fixture f("controller_nodir");
    SessionController c(f.clock(), RecoveryDir("/proc/gbuffer-lab-recovery"), 5007);
    c.start(f.state, 32);
    EXPECT_FALSE(c.recovery());
    ASSERT_FALSE(f.state.log.lines.empty());
    EXPECT_NE(f.state.log.lines.back().find("crash recovery is off"), std::string::npos);
    f.state.lights[0].kc = 2.0f;
    f.run(c, 5.0);  // and the editor goes on working
    EXPECT_EQ(c.autosaves(), 0);
}

TEST(SessionController, KnowsWhenEditsAreUnsaved) {
    Fixture f("controller_dirty");
    SessionController c(f.clock(), std::nullopt, 5007);
    c.start(f.state, 32);
    EXPECT_FALSE(c.hasUnsavedEdits(f.state));
    // Looking around is not an edit.
    f.state.camera.position.x += 3.0f;
    f.state.animation.time = 2.5f;
    EXPECT_FALSE(c.hasUnsavedEdits(f.state));
    f.state.lights[1].intensity = 4.0f;
    EXPECT_TRUE(c.hasUnsavedEdits(f.state));
    std::string const path = f.dir + "/saved.json";
    ASSERT_EQ(c.saveSession(path, f.state), std::nullopt);
    EXPECT_FALSE(c.hasUnsavedEdits(f.state)) << "saved";
    f.state.pipeline.exposure = 3.0f;
    EXPECT_TRUE(c.hasUnsavedEdits(f.state));
    ASSERT_EQ(c.openSession(path, f.state, f.loader()), std::nullopt);
    EXPECT_FALSE(c.hasUnsavedEdits(f.state)) << "opened: what is shown is what the file holds";
    EXPECT_EQ(f.state.pipeline.exposure, 1.0f);
}

TEST(SessionController, ALessonsStepsAreNotEditsButEditsBeforeAndDuringOneAre) {
    Fixture f("controller_lesson");
    SessionController c(f.clock(), std::nullopt, 5007);
    c.start(f.state, 32);
    EditorState const before = f.state;
    // A lesson opens: its step changes the lights and the pipeline, and that is not an edit.
    c.lessonStarting(f.state);
    f.state.lights.resize(1);
    f.state.pipeline.mode = LightingMode::Volumes;
    c.lessonStepShown(f.state);
    EXPECT_FALSE(c.hasUnsavedEdits(f.state)) << "only a lesson step is shown";
    // Auto-fit refitting a viewer's range is not an edit either.
    f.state.gbuffer.viewers[0].autoFit = true;
    c.lessonStepShown(f.state);
    f.state.gbuffer.viewers[0].rangeMax = 7.0f;
    EXPECT_FALSE(c.hasUnsavedEdits(f.state)) << "an auto-fitted range";
    // The student's own change during the step is.
    f.state.lights[0].intensity = 4.0f;
    EXPECT_TRUE(c.hasUnsavedEdits(f.state));
    // Leaving restores the editor: nothing unsaved again.
    f.state = before;
    c.lessonLeft();
    EXPECT_FALSE(c.hasUnsavedEdits(f.state));
    // Edits made before a lesson stay unsaved while it runs (they wait in its return state).
    f.state.lights[1].intensity = 4.0f;
    c.lessonStarting(f.state);
    f.state.lights.resize(1);
    c.lessonStepShown(f.state);
    EXPECT_TRUE(c.hasUnsavedEdits(f.state));
}

// With another program's G-buffer open the lights shown are the G-buffer's: saving, autosaving
// and the unsaved-edits question still speak of the scene behind it (model/gbuffer_opening.h).
TEST(SessionController, WithAGBufferOpenSessionsStoreTheSceneBehindIt) {
    Fixture f("controller_gbuffer");
    SessionController c(f.clock(), RecoveryDir(f.dir), 5008, {3.0, 20.0});
    for (std::size_t i = 0; i < f.state.lights.size(); ++i) f.state.lights[i].intensity = 1.0f + float(i);
    c.start(f.state, 32);
    GBufferOpenState gbuffer;
    c.setSceneBehind([&gbuffer](EditorState const& s) -> std::optional<EditorState> {
        if (!gbufferOpen(gbuffer)) return std::nullopt;
        return sceneBehind(s, gbuffer);
    });
    // Open by hand, as installGBuffer leaves things: the scene kept, the G-buffer's two lights shown.
    gbuffer.path = "/x/their_gbuffer";
    gbuffer.scene = SceneViewSnapshot{
        f.state.camera,          f.state.rig, f.state.lights, 1, f.state.pipeline.shininess, f.state.pipeline.shading,
        f.state.pipeline.ambient};
    f.state.lights.assign(2, PointLight{});
    f.state.lights[0].intensity = 9.0f;
    EXPECT_FALSE(c.hasUnsavedEdits(f.state)) << "the G-buffer's lights are not an edit of the scene";
    f.state.lights[1].intensity = 7.0f;  // a light of the G-buffer tweaked
    f.run(c, 10.0);
    EXPECT_EQ(c.autosaves(), 0) << "the scene did not change";

    std::string const path = f.dir + "/saved.json";
    ASSERT_EQ(c.saveSession(path, f.state), std::nullopt);
    SessionLoad const saved = loadSession(path);
    ASSERT_TRUE(saved.session) << saved.error;
    ASSERT_EQ(saved.session->lights.size(), 4u) << "the scene's lights, not the G-buffer's two";
    for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(saved.session->lights[i].intensity, 1.0f + float(i));
    EXPECT_EQ(saved.session->scene, "default");

    // Closed: the scene's lights are shown again and sessions speak of what is shown.
    closeGBuffer(gbuffer, f.state);
    EXPECT_EQ(f.state.lights.size(), 4u);
    f.state.lights[3].intensity = 0.5f;
    EXPECT_TRUE(c.hasUnsavedEdits(f.state));
    c.endCleanly();
}

TEST(SessionController, LookingAroundIsNotAutosavedAndNothingIsOfferedForIt) {
    // A page reloaded with no input, or a camera moved and the tab closed: nothing the student
    // changed, so the next start offers nothing.
    Fixture f("controller_look_around");
    RecoveryDir const dir(f.dir);
    long const gone = deadPid();
    {
        SessionController c(f.clock(), dir, gone);
        c.start(f.state, 32);
        f.state.camera.position.x += 3.0f;
        f.state.animation.time += 2.0f;
        f.run(c, 25.0);
        EXPECT_EQ(c.autosaves(), 0);
        EXPECT_FALSE(fs::exists(dir.sessionPath(gone)));
    }  // no endCleanly: the page went as a reload leaves it
    SessionController next(f.clock(), dir, 5010);
    next.start(f.state, 32);
    EXPECT_FALSE(next.panel.recoveryOffer);
}

TEST(SessionController, SavingOrUndoingTheEditsRemovesTheAutosave) {
    Fixture f("controller_saved_edits");
    SessionController c(f.clock(), RecoveryDir(f.dir), 5011, {3.0, 20.0});
    c.start(f.state, 32);
    f.state.lights[1].intensity = 4.5f;
    f.run(c, 4.0);
    ASSERT_EQ(c.autosaves(), 1);
    ASSERT_TRUE(fs::exists(c.recoveryPath()));
    ASSERT_EQ(c.saveSession(f.dir + "/saved.json", f.state), std::nullopt);
    EXPECT_FALSE(fs::exists(c.recoveryPath())) << "saved: a reload has nothing to offer";

    f.state.lights[1].intensity = 9.0f;
    f.run(c, 4.0);
    ASSERT_EQ(c.autosaves(), 2);
    ASSERT_TRUE(fs::exists(c.recoveryPath()));
    f.state.lights[1].intensity = 4.5f;  // back to what was saved
    f.run(c, 4.0);
    EXPECT_EQ(c.autosaves(), 2);
    EXPECT_FALSE(fs::exists(c.recoveryPath())) << "undone: nothing unsaved is left to offer";
}

TEST(SessionController, TheOfferSaysHowOldTheChangesAreInWords) {
    Fixture f("controller_offer_words");
    RecoveryDir const dir(f.dir);
    long const gone = deadPid();
    ASSERT_EQ(dir.beginRun(gone), std::nullopt);
    Session lost = captureSession(f.state, 32);
    lost.lights.resize(6);
    ASSERT_EQ(saveSession(dir.sessionPath(gone), lost), std::nullopt);
    fs::last_write_time(dir.sessionPath(gone), fs::file_time_type::clock::now() - std::chrono::seconds(190));
    SessionController c(f.clock(), dir, 5012);
    c.start(f.state, 32);
    ASSERT_TRUE(c.panel.recoveryOffer);
    EXPECT_EQ(c.panel.recoveryTitle, "Your changes from 3 minutes ago were not saved.");
    EXPECT_EQ(c.panel.recoveryWhy, "They can be restored: 6 lights, the default scene.");
    EXPECT_NE(c.panel.recoveryCause.find("did not exit cleanly"), std::string::npos) << c.panel.recoveryCause;
}

TEST(Recovery, AgeInWords) {
    EXPECT_EQ(ageInWords(5.0), "a moment ago");
    EXPECT_EQ(ageInWords(61.0), "1 minute ago");
    EXPECT_EQ(ageInWords(179.0), "2 minutes ago");
    EXPECT_EQ(ageInWords(3 * 3600.0 + 5.0), "3 hours ago");
    EXPECT_EQ(ageInWords(3 * 86400.0), "3 days ago");
}
