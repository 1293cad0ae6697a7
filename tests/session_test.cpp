// Session files: exact round trips, old files read with the defaults of what they lack, atomic
// writes. One clear message per kind of bad field: session_errors_test.
#include "session/session.h"
#include "core/json_fields.h"
#include "run_command.h"
#include "session/atomic_file.h"
#include "session_samples.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/resource.h>

#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

using namespace gbl;
using namespace gbl::ui;
using gbl::test::richSession;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

// Bitwise float comparison: a session must reproduce the same frame, not a similar one.
void expectSame(float a, float b, std::string const& what) {
    EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << what << ": " << a << " vs " << b;
}
template <int N>
void expectSame(glm::vec<N, float> a, glm::vec<N, float> b, std::string const& what) {
    for (int i = 0; i < N; ++i) expectSame(a[i], b[i], what + "[" + std::to_string(i) + "]");
}

void expectEqual(Session const& a, Session const& b) {
    EXPECT_EQ(a.scene, b.scene);
    EXPECT_EQ(a.defaultSceneLights, b.defaultSceneLights);
    expectSame(a.camera.position, b.camera.position, "camera.position");
    expectSame(a.camera.yawDegrees, b.camera.yawDegrees, "yaw");
    expectSame(a.camera.pitchDegrees, b.camera.pitchDegrees, "pitch");
    expectSame(a.camera.fovYDegrees, b.camera.fovYDegrees, "fov");
    expectSame(a.camera.nearPlane, b.camera.nearPlane, "near");
    expectSame(a.camera.farPlane, b.camera.farPlane, "far");
    ASSERT_EQ(a.lights.size(), b.lights.size());
    for (std::size_t i = 0; i < a.lights.size(); ++i) {
        auto const &x = a.lights[i], &y = b.lights[i];
        std::string const at = "lights[" + std::to_string(i) + "].";
        expectSame(x.position, y.position, at + "position");
        expectSame(x.color, y.color, at + "color");
        expectSame(x.intensity, y.intensity, at + "intensity");
        expectSame(x.kc, y.kc, at + "kc");
        expectSame(x.kl, y.kl, at + "kl");
        expectSame(x.kq, y.kq, at + "kq");
        expectSame(x.threshold, y.threshold, at + "threshold");
        EXPECT_EQ(x.kind, y.kind) << at << "kind";
        expectSame(x.direction, y.direction, at + "direction");
        expectSame(x.innerConeDeg, y.innerConeDeg, at + "inner_cone_deg");
        expectSame(x.outerConeDeg, y.outerConeDeg, at + "outer_cone_deg");
        EXPECT_EQ(x.name, y.name);
    }
    PipelineSettings const &p = a.pipeline, &q = b.pipeline;
    EXPECT_EQ(p.mode, q.mode);
    EXPECT_EQ(p.cull, q.cull);
    EXPECT_EQ(p.depthCopy, q.depthCopy);
    EXPECT_EQ(p.tonemap, q.tonemap);
    EXPECT_EQ(p.view, q.view);
    EXPECT_EQ(p.lightCubes, q.lightCubes);
    EXPECT_EQ(p.volumeWireframes, q.volumeWireframes);
    EXPECT_EQ(p.normalMaps, q.normalMaps);
    EXPECT_EQ(p.wireframesSelectedOnly, q.wireframesSelectedOnly);
    EXPECT_EQ(p.layout, q.layout);
    EXPECT_EQ(p.accumulation, q.accumulation);
    expectSame(p.volumeScale, q.volumeScale, "volume_scale");
    expectSame(p.ambient, q.ambient, "ambient");
    expectSame(p.exposure, q.exposure, "exposure");
    expectSame(p.shininess, q.shininess, "shininess");
    for (std::size_t i = 0; i < a.viewers.size(); ++i) {
        auto const &v = a.viewers[i], &w = b.viewers[i];
        std::string const at = "viewers." + std::string(kViewerNames[i]) + ".";
        EXPECT_EQ(v.kind, w.kind) << at;
        EXPECT_EQ(v.channelMask, w.channelMask) << at;
        expectSame(v.rangeMin, w.rangeMin, at + "range_min");
        expectSame(v.rangeMax, w.rangeMax, at + "range_max");
        EXPECT_EQ(v.autoFit, w.autoFit) << at;
        EXPECT_EQ(v.normalDisplay, w.normalDisplay) << at;
        EXPECT_EQ(v.linearDepth, w.linearDepth) << at;
        EXPECT_EQ(v.cameraClipPlanes, w.cameraClipPlanes) << at;
        expectSame(v.nearPlane, w.nearPlane, at + "near");
        expectSame(v.farPlane, w.farPlane, at + "far");
        expectSame(v.zoom, w.zoom, at + "zoom");
        expectSame(v.center, w.center, at + "center");
        EXPECT_EQ(v.colormap, w.colormap) << at;
        EXPECT_EQ(v.overlays, w.overlays) << at;
        EXPECT_EQ(v.showHistogram, w.showHistogram) << at;
        EXPECT_EQ(v.showStencil, w.showStencil) << at;
    }
    EXPECT_EQ(a.syncViews, b.syncViews);
    EXPECT_EQ(a.viewportToolsOpen, b.viewportToolsOpen);
    EXPECT_EQ(a.viewportViewer.channelMask, b.viewportViewer.channelMask);
    expectSame(a.viewportViewer.rangeMin, b.viewportViewer.rangeMin, "viewport range_min");
    expectSame(a.viewportViewer.rangeMax, b.viewportViewer.rangeMax, "viewport range_max");
    EXPECT_EQ(a.viewportViewer.colormap, b.viewportViewer.colormap);
    EXPECT_EQ(a.viewportViewer.overlays, b.viewportViewer.overlays);
    EXPECT_EQ(a.viewportViewer.showHistogram, b.viewportViewer.showHistogram);
    EXPECT_EQ(a.animation.enabled, b.animation.enabled);
    expectSame(a.animation.speed, b.animation.speed, "animation.speed");
    expectSame(a.animation.time, b.animation.time, "animation.time");
}

}  // namespace

// --- round trips --------------------------------------------------------------------------

TEST(Session, RoundTripKeepsEveryFieldBitExact) {
    Session const s = richSession();
    SessionLoad const back = parseSession(sessionToJson(s), "s.json");
    ASSERT_TRUE(back.session) << back.error;
    expectEqual(s, *back.session);
    // Writing it again gives the same text: nothing drifts over repeated saves.
    EXPECT_EQ(sessionToJson(*back.session), sessionToJson(s));
}

TEST(Session, DefaultSessionRoundTrips) {
    Session const s;
    SessionLoad const back = parseSession(sessionToJson(s), "s.json");
    ASSERT_TRUE(back.session) << back.error;
    expectEqual(s, *back.session);
}

TEST(Session, FileRoundTripThroughSaveAndLoad) {
    std::string const dir = test::freshTempDir("session_file");
    std::string const path = dir + "/a.json";
    ASSERT_EQ(saveSession(path, richSession()), std::nullopt);
    SessionLoad const back = loadSession(path);
    ASSERT_TRUE(back.session) << back.error;
    expectEqual(richSession(), *back.session);
}

TEST(Session, FileCarriesFormatAndVersion) {
    json const j = json::parse(sessionToJson(Session{}));
    EXPECT_EQ(j["format"], "gbuffer-lab-session");
    EXPECT_EQ(j["version"], 1);
    EXPECT_EQ(j["pipeline"]["depth_copy"], "blit");  // enums by name, as on the command line
    EXPECT_FALSE(j["pipeline"].contains("blit")) << "the depth copy's old key is read, never written";
    EXPECT_EQ(j["pipeline"]["cull"], "front");
}

TEST(Session, GBufferLayoutIsSavedAndOldFilesLoadAsClassic) {
    Session s;
    s.pipeline.layout = GBufferLayout::Packed;
    json j = json::parse(sessionToJson(s));
    EXPECT_EQ(j["pipeline"]["layout"], "packed");
    SessionLoad const back = parseSession(j.dump(), "s.json");
    ASSERT_TRUE(back.session) << back.error;
    EXPECT_EQ(back.session->pipeline.layout, GBufferLayout::Packed);
    // A file written before layouts existed has no pipeline.layout.
    j["pipeline"].erase("layout");
    SessionLoad const old = parseSession(j.dump(), "s.json");
    ASSERT_TRUE(old.session) << old.error;
    EXPECT_EQ(old.session->pipeline.layout, GBufferLayout::Classic);
    j["pipeline"]["layout"] = "tiny";
    SessionLoad const bad = parseSession(j.dump(), "s.json");
    EXPECT_FALSE(bad.session);
    EXPECT_NE(bad.error.find("pipeline.layout"), std::string::npos) << bad.error;
}

TEST(Session, AccumulationIsSavedAndOldFilesLoadAsSingle) {
    Session s;
    s.pipeline.accumulation = LightAccumulation::Split;
    json j = json::parse(sessionToJson(s));
    EXPECT_EQ(j["pipeline"]["accumulation"], "split");
    SessionLoad const back = parseSession(j.dump(), "s.json");
    ASSERT_TRUE(back.session) << back.error;
    EXPECT_EQ(back.session->pipeline.accumulation, LightAccumulation::Split);
    // A file written before the split targets existed has no pipeline.accumulation.
    j["pipeline"].erase("accumulation");
    SessionLoad const old = parseSession(j.dump(), "s.json");
    ASSERT_TRUE(old.session) << old.error;
    EXPECT_EQ(old.session->pipeline.accumulation, LightAccumulation::Single);
    j["pipeline"]["accumulation"] = "double";
    SessionLoad const bad = parseSession(j.dump(), "s.json");
    EXPECT_FALSE(bad.session);
    EXPECT_NE(bad.error.find("pipeline.accumulation"), std::string::npos) << bad.error;
}

// msaa (issue 47, docs/msaa.md): both settings saved by name; a file written before them loads with
// msaa off and the edges strategy; a value that is none of the names is one message naming the key.
TEST(Session, MsaaIsSavedAndOldFilesLoadWithMsaaOff) {
    Session s;
    s.pipeline.msaa = Msaa::X8;
    s.pipeline.msaaLighting = MsaaLighting::PerSample;
    json j = json::parse(sessionToJson(s));
    EXPECT_EQ(j["pipeline"]["msaa"], "8");
    EXPECT_EQ(j["pipeline"]["msaa_lighting"], "per-sample");
    SessionLoad const back = parseSession(j.dump(), "s.json");
    ASSERT_TRUE(back.session) << back.error;
    EXPECT_EQ(back.session->pipeline.msaa, Msaa::X8);
    EXPECT_EQ(back.session->pipeline.msaaLighting, MsaaLighting::PerSample);
    j["pipeline"].erase("msaa");
    j["pipeline"].erase("msaa_lighting");
    SessionLoad const old = parseSession(j.dump(), "s.json");
    ASSERT_TRUE(old.session) << old.error;
    EXPECT_EQ(old.session->pipeline.msaa, Msaa::Off);
    EXPECT_EQ(old.session->pipeline.msaaLighting, MsaaLighting::Edges);
    j["pipeline"]["msaa"] = "16";
    SessionLoad const bad = parseSession(j.dump(), "s.json");
    EXPECT_FALSE(bad.session);
    EXPECT_NE(bad.error.find("pipeline.msaa"), std::string::npos) << bad.error;
}

// The glass (issue 47): the default scene's panes under scene.default_scene_glass, written only when
// on (sessions without glass keep their text), and the glass_outline overlay among the pipeline fields.
TEST(Session, GlassIsSavedOnlyWhenOnAndOldFilesLoadWithout) {
    Session s;
    json j = json::parse(sessionToJson(s));
    EXPECT_FALSE(j["scene"].contains("default_scene_glass"));
    EXPECT_EQ(j["pipeline"]["glass_outline"], false);
    s.defaultSceneGlass = true;
    s.pipeline.glassOutline = true;
    j = json::parse(sessionToJson(s));
    EXPECT_EQ(j["scene"]["default_scene_glass"], true);
    SessionLoad const back = parseSession(j.dump(), "s.json");
    ASSERT_TRUE(back.session) << back.error;
    EXPECT_TRUE(back.session->defaultSceneGlass);
    EXPECT_TRUE(back.session->pipeline.glassOutline);
    j["scene"].erase("default_scene_glass");
    j["pipeline"].erase("glass_outline");
    SessionLoad const old = parseSession(j.dump(), "s.json");
    ASSERT_TRUE(old.session) << old.error;
    EXPECT_FALSE(old.session->defaultSceneGlass);
    EXPECT_FALSE(old.session->pipeline.glassOutline);
    j["scene"]["default_scene_glass"] = "yes";
    SessionLoad const bad = parseSession(j.dump(), "s.json");
    EXPECT_FALSE(bad.session);
    EXPECT_NE(bad.error.find("scene.default_scene_glass"), std::string::npos) << bad.error;
}

TEST(Session, LightNameIsOptional) {
    json j = json::parse(sessionToJson(richSession()));
    j["lights"][0].erase("name");
    SessionLoad const back = parseSession(j.dump(), "s.json");
    ASSERT_TRUE(back.session) << back.error;
    EXPECT_EQ(back.session->lights[0].name, "");
}

TEST(Session, LightKindsAreSavedAndOldFilesLoadAsPoints) {
    json j = json::parse(sessionToJson(richSession()));
    EXPECT_EQ(j["lights"][1]["kind"], "spot");
    EXPECT_EQ(j["lights"][3]["kind"], "directional");
    EXPECT_EQ(j["lights"][0]["kind"], "point");
    // A file written before light kinds has none of the four fields.
    for (auto& l : j["lights"])
        for (char const* f : {"kind", "direction", "inner_cone_deg", "outer_cone_deg"}) l.erase(f);
    SessionLoad const old = parseSession(j.dump(), "s.json");
    ASSERT_TRUE(old.session) << old.error;
    for (PointLight const& l : old.session->lights) {
        EXPECT_EQ(l.kind, LightKind::Point);
        EXPECT_EQ(l.direction, PointLight{}.direction);
        EXPECT_EQ(l.outerConeDeg, PointLight{}.outerConeDeg);
    }
}

TEST(Session, EveryLightFieldOfTheTableIsWrittenAndReadUnderItsKey) {
    // The light's keys in the file are exactly the table's (core/json_fields.h lightFileKeys), in
    // its order; each entry edited alone survives the round trip under its own key.
    auto const j = nlohmann::ordered_json::parse(sessionToJson(richSession()));
    std::vector<std::string> keys;
    for (auto const& [key, value] : j["lights"][1].items()) keys.push_back(key);
    std::vector<std::string> expected;
    for (std::string_view k : json_fields::lightFileKeys()) expected.emplace_back(k);
    EXPECT_EQ(keys, expected);
    for (LightField const& f : kLightFields) {
        Session s = richSession();
        f.of(s.lights[1]) += f.range == LightFieldRange::ConeAngle ? -1.0f : 0.25f;
        json const written = json::parse(sessionToJson(s));
        json const& v = written["lights"][1][std::string(f.fileKey)];
        EXPECT_EQ(f.vector ? v[std::size_t(f.component)].get<float>() : v.get<float>(), f.of(s.lights[1])) << f.name;
        SessionLoad const back = parseSession(written.dump(), "s.json");
        ASSERT_TRUE(back.session) << f.name << ": " << back.error;
        EXPECT_EQ(f.of(back.session->lights[1]), f.of(s.lights[1])) << f.name;
        // A required key missing is named; an optional one leaves the default.
        json without = written;
        without["lights"][1].erase(std::string(f.fileKey));
        SessionLoad const older = parseSession(without.dump(), "s.json");
        if (f.optionalInFiles) {
            ASSERT_TRUE(older.session) << f.name << ": " << older.error;
            EXPECT_EQ(f.of(older.session->lights[1]), f.of(PointLight{})) << f.name;
        } else {
            EXPECT_EQ(older.error, "s.json: lights[1]." + std::string(f.fileKey) + " is missing") << f.name;
        }
    }
}

TEST(Session, ViewerToolsAreWrittenByName) {
    json const j = json::parse(sessionToJson(richSession()));
    json const& depth = j["viewers"]["depth"]["tools"];
    EXPECT_EQ(depth["stencil"], true);
    EXPECT_EQ(depth["colormap"], "turbo");                                                // Colormap(4 % 3)
    EXPECT_EQ(depth["overlays"], json::array({"negative", "clip"}));                      // 12 = 4 + 8
    EXPECT_EQ(j["viewers"]["normal"]["tools"]["overlays"], json::array({"nan", "inf"}));  // 3
    EXPECT_EQ(j["viewer_tools"]["sync"], true);
    EXPECT_EQ(j["viewer_tools"]["viewport"]["open"], true);
    EXPECT_EQ(j["viewer_tools"]["viewport"]["viewer"]["tools"]["colormap"], "viridis");
}

TEST(Session, FileWithoutViewerToolsLoadsWithTheirDefaults) {
    // A version 1 file from before the viewer tools: no "tools", no "viewer_tools".
    json j = json::parse(sessionToJson(richSession()));
    for (auto& [name, viewer] : j["viewers"].items()) viewer.erase("tools");
    j.erase("viewer_tools");
    SessionLoad const back = parseSession(j.dump(), "old.json");
    ASSERT_TRUE(back.session) << back.error;
    ViewerState const defaults;
    for (ViewerState const& v : back.session->viewers) {
        EXPECT_EQ(v.colormap, defaults.colormap);
        EXPECT_EQ(v.overlays, 0u);
        EXPECT_FALSE(v.showHistogram);
        EXPECT_FALSE(v.showStencil);
    }
    EXPECT_FALSE(back.session->syncViews);
    EXPECT_FALSE(back.session->viewportToolsOpen);
    // The rest is read as before.
    expectSame(back.session->viewers[2].rangeMin, richSession().viewers[2].rangeMin, "albedo range_min");
    // Each tool field alone is optional too.
    json k = json::parse(sessionToJson(richSession()));
    k["viewers"]["albedo"]["tools"].erase("colormap");
    k["viewer_tools"].erase("viewport");
    SessionLoad const partial = parseSession(k.dump(), "k.json");
    ASSERT_TRUE(partial.session) << partial.error;
    EXPECT_EQ(partial.session->viewers[2].colormap, Colormap::Grey);
    EXPECT_EQ(partial.session->viewers[2].overlays, richSession().viewers[2].overlays);
    EXPECT_TRUE(partial.session->syncViews);
}

// --- atomic writes --------------------------------------------------------------------------

namespace {

std::string slurp(std::string const& path) {
    std::ifstream f(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), {});
}

std::vector<std::string> filesIn(std::string const& dir) {
    std::vector<std::string> names;
    for (auto const& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// Lowers the file size limit for the scope, so writes past `bytes` fail with EFBIG: a real
// failing write (like a full disk) that also works when the tests run as root.
struct FileSizeLimit {
    rlimit old{};
    void (*oldHandler)(int) = nullptr;
    explicit FileSizeLimit(rlim_t bytes) {
        getrlimit(RLIMIT_FSIZE, &old);
        oldHandler = std::signal(SIGXFSZ, SIG_IGN);  // else the kernel kills the process
        rlimit l = old;
        l.rlim_cur = bytes;
        setrlimit(RLIMIT_FSIZE, &l);
    }
    ~FileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &old);
        std::signal(SIGXFSZ, oldHandler);
    }
};

}  // namespace

TEST(AtomicWrite, CreatesAndReplacesLeavingNoTemporaryFiles) {
    std::string const dir = test::freshTempDir("atomic_ok");
    std::string const path = dir + "/s.json";
    ASSERT_EQ(writeFileAtomically(path, "first"), std::nullopt);
    EXPECT_EQ(slurp(path), "first");
    ASSERT_EQ(writeFileAtomically(path, "second, longer"), std::nullopt);
    EXPECT_EQ(slurp(path), "second, longer");
    EXPECT_EQ(filesIn(dir), std::vector<std::string>{"s.json"});
}

TEST(AtomicWrite, FailedWriteLeavesTheOldFileIntact) {
    std::string const dir = test::freshTempDir("atomic_fail");
    std::string const path = dir + "/session.json";
    std::string const old = sessionToJson(richSession());
    ASSERT_EQ(writeFileAtomically(path, old), std::nullopt);

    Session bigger = richSession();
    bigger.lights.assign(2000, PointLight{});
    std::string const replacement = sessionToJson(bigger);
    std::optional<std::string> error;
    {
        // Room for part of the new file only: the write fails half way through.
        FileSizeLimit limit(4096);
        ASSERT_GT(replacement.size(), 4096u);
        error = saveSession(path, bigger);
    }
    ASSERT_TRUE(error);
    EXPECT_NE(error->find(path), std::string::npos) << *error;
    EXPECT_NE(error->find("writing failed"), std::string::npos) << *error;
    EXPECT_EQ(slurp(path), old);  // every byte of the previous session is still there
    EXPECT_EQ(filesIn(dir), std::vector<std::string>{"session.json"});  // no temporary left behind
    SessionLoad const back = loadSession(path);
    ASSERT_TRUE(back.session) << back.error;
    expectEqual(richSession(), *back.session);
}

TEST(AtomicWrite, UnwritableDestinationsAreMessages) {
    std::string const dir = test::freshTempDir("atomic_bad");
    auto const noDir = writeFileAtomically(dir + "/missing/s.json", "x");
    ASSERT_TRUE(noDir);
    EXPECT_NE(noDir->find(dir + "/missing/s.json"), std::string::npos) << *noDir;
    auto const isDir = writeFileAtomically(dir, "x");
    ASSERT_TRUE(isDir);
    EXPECT_NE(isDir->find("is a directory"), std::string::npos) << *isDir;
    EXPECT_TRUE(fs::is_directory(dir));
    // /proc refuses new files even to root.
    auto const proc = writeFileAtomically("/proc/gbuffer-lab-session.json", "x");
    ASSERT_TRUE(proc);
    EXPECT_NE(proc->find("/proc/gbuffer-lab-session.json"), std::string::npos) << *proc;
}
