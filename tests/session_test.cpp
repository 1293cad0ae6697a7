// Session files: exact round trips, one clear message per kind of bad field, atomic writes.
#include "session/session.h"
#include "core/json_fields.h"
#include "run_command.h"
#include "session/atomic_file.h"

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
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

// Every field away from its default, with floats that have no short decimal form, so a
// round trip that loses precision or drops a field fails.
Session richSession() {
    Session s;
    s.scene = "/models/Sponza \"quoted\"/Sponza.gltf";
    s.defaultSceneLights = 7;
    s.camera.position = {1.0f / 3.0f, -2.7182817f, 1e-7f};
    s.camera.yawDegrees = -123.456f;
    s.camera.pitchDegrees = 12.3456789f;
    s.camera.fovYDegrees = 47.5f;
    s.camera.nearPlane = 0.0123f;
    s.camera.farPlane = 345.6f;
    for (int i = 0; i < 5; ++i) {
        PointLight l;
        l.position = {float(i) * 0.1f, 3.14159265f, -float(i) / 7.0f};
        l.color = {0.9f, 0.1f * float(i), 1.0f / 3.0f};
        l.intensity = 1.0f + float(i) / 9.0f;
        l.kc = 1.0f;
        l.kl = 0.07f + float(i) * 0.011f;
        l.kq = i == 4 ? 0.0f : 0.017f * float(i + 1);
        l.threshold = 5.0f / 256.0f;
        l.name = i == 2 ? "lämp \"two\"\n" : "light " + std::to_string(i);
        // One of each kind beyond points, with every kind field off its default.
        if (i == 1 || i == 3) {
            l.kind = i == 1 ? LightKind::Spot : LightKind::Directional;
            l.direction = {0.1f * float(i), -1.0f / 3.0f, 0.7071068f};
            l.innerConeDeg = 12.345f;
            l.outerConeDeg = 33.3f;
        }
        s.lights.push_back(l);
    }
    s.pipeline.mode = LightingMode::Volumes;
    s.pipeline.cull = CullMode::Stencil;
    s.pipeline.depthCopy = DepthCopy::Shader;
    s.pipeline.tonemap = Tonemap::Reinhard;
    s.pipeline.view = DebugView::DepthLinear;
    s.pipeline.lightCubes = false;
    s.pipeline.volumeWireframes = true;
    s.pipeline.normalMaps = false;
    s.pipeline.ambient = {0.01f, 0.02f, 0.0333f};
    s.pipeline.exposure = 1.7f;
    s.pipeline.shininess = 64.5f;
    s.pipeline.wireframesSelectedOnly = true;
    for (std::size_t i = 0; i < s.viewers.size(); ++i) {
        ViewerState& v = s.viewers[i];
        v.channelMask = unsigned(i + 1);
        v.rangeMin = -10.5f + float(i);
        v.rangeMax = 12.25f / 3.0f + float(i);
        v.autoFit = i % 2 == 0;
        v.normalDisplay = i % 2 ? NormalDisplay::Absolute : NormalDisplay::Biased;
        v.linearDepth = i % 2 == 1;
        v.cameraClipPlanes = i % 3 == 0;
        v.nearPlane = 0.5f + float(i);
        v.farPlane = 50.0f + float(i) / 3.0f;
        v.zoom = 1.0f + float(i) * 2.5f;
        v.center = {0.25f + float(i) * 0.1f, 0.75f - float(i) * 0.1f};
        v.colormap = Colormap(i % 3);
        v.overlays = unsigned(i * 3) & 0xFu;  // 0, nan+inf, negative+inf, ...
        v.showHistogram = i % 2 == 1;
    }
    s.viewers[4].showStencil = true;  // only the depth viewer shows it
    s.syncViews = true;
    s.viewportToolsOpen = true;
    s.viewportViewer.channelMask = 0x2;
    s.viewportViewer.rangeMin = -0.125f / 3.0f;
    s.viewportViewer.rangeMax = 7.0f / 3.0f;
    s.viewportViewer.colormap = Colormap::Viridis;
    s.viewportViewer.overlays = kOverlayNaN | kOverlayClip;
    s.viewportViewer.showHistogram = true;
    s.animation.enabled = true;
    s.animation.speed = 0.35f;
    s.animation.time = 12.345678f;
    return s;
}

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

// --- bad fields -----------------------------------------------------------------------------

namespace {

struct BadCase {
    char const* what;
    std::function<void(json&)> edit;
    std::string message;  // the whole expected message
};

}  // namespace

TEST(Session, EveryKindOfBadFieldGetsOneMessageNamingIt) {
    std::vector<BadCase> const cases{
        // unknown fields, at every level
        {"unknown top-level field", [](json& j) { j["colour_grading"] = true; },
         "s.json: colour_grading is not a known field"},
        {"typo in a light field", [](json& j) { j["lights"][2]["intesity"] = 2; },
         "s.json: lights[2].intesity is not a known field"},
        {"unknown pipeline field", [](json& j) { j["pipeline"]["ssao"] = true; },
         "s.json: pipeline.ssao is not a known field"},
        {"unknown viewer", [](json& j) { j["viewers"]["emission"] = j["viewers"]["albedo"]; },
         "s.json: viewers.emission is not a known field"},
        // missing required fields
        {"missing camera.near", [](json& j) { j["camera"].erase("near"); }, "s.json: camera.near is missing"},
        {"missing kq", [](json& j) { j["lights"][1].erase("kq"); }, "s.json: lights[1].kq is missing"},
        {"missing lights", [](json& j) { j.erase("lights"); }, "s.json: lights is missing"},
        {"missing viewer", [](json& j) { j["viewers"].erase("depth"); }, "s.json: viewers.depth is missing"},
        {"missing format", [](json& j) { j.erase("format"); }, "s.json: format is missing"},
        // wrong types
        {"kq as a string", [](json& j) { j["lights"][3]["kq"] = "1.8"; },
         "s.json: lights[3].kq must be a finite number >= 0 (got a string)"},
        {"bool as a number", [](json& j) { j["pipeline"]["light_cubes"] = 1; },
         "s.json: pipeline.light_cubes must be true or false (got a number)"},
        {"lights as an object", [](json& j) { j["lights"] = json::object(); },
         "s.json: lights must be an array (got an object)"},
        {"light as an array", [](json& j) { j["lights"][0] = json::array(); },
         "s.json: lights[0] must be an object (got an array)"},
        {"short vector",
         [](json& j) {
             j["camera"]["position"] = {1, 2};
         },
         "s.json: camera.position must be an array of 3 numbers"},
        {"vector element", [](json& j) { j["lights"][4]["color"][1] = true; },
         "s.json: lights[4].color[1] must be a finite number >= 0 (got true/false)"},
        {"fractional mask", [](json& j) { j["viewers"]["albedo"]["channel_mask"] = 1.5; },
         "s.json: viewers.albedo.channel_mask must be a whole number from 0 to 15 (got 1.5)"},
        // NaN, infinity, negative: JSON writers turn NaN into null; 1e39 is finite as a double
        // but infinite as the float the renderer uses.
        {"NaN written as null", [](json& j) { j["lights"][3]["kq"] = nullptr; },
         "s.json: lights[3].kq must be a finite number >= 0 (got null)"},
        {"float overflow", [](json& j) { j["lights"][3]["intensity"] = 1e39; },
         "s.json: lights[3].intensity must be a finite number >= 0 (got 1e+39)"},
        {"negative kq", [](json& j) { j["lights"][3]["kq"] = -0.5; },
         "s.json: lights[3].kq must be a finite number >= 0 (got -0.5)"},
        {"negative colour", [](json& j) { j["lights"][0]["color"][2] = -1; },
         "s.json: lights[0].color[2] must be a finite number >= 0 (got -1)"},
        {"zero threshold", [](json& j) { j["lights"][0]["threshold"] = 0; },
         "s.json: lights[0].threshold must be a finite number > 0 (got 0)"},
        {"infinite position", [](json& j) { j["lights"][1]["position"][0] = -1e300; },
         "s.json: lights[1].position[0] must be a finite number (got -1e+300)"},
        {"no attenuation at all",
         [](json& j) {
             j["lights"][2]["kc"] = 0;
             j["lights"][2]["kl"] = 0;
             j["lights"][2]["kq"] = 0;
         },
         "s.json: lights[2]: light attenuation Kc, Kl and Kq cannot all be 0 (infinite brightness at the light)"},
        {"unknown light kind", [](json& j) { j["lights"][0]["kind"] = "area"; },
         "s.json: lights[0].kind must be one of point, spot or directional (got \"area\")"},
        {"zero direction",
         [](json& j) {
             j["lights"][1]["direction"] = {0, 0, 0};
         },
         "s.json: lights[1].direction must not be the zero vector"},
        {"non-finite direction", [](json& j) { j["lights"][1]["direction"][2] = nullptr; },
         "s.json: lights[1].direction[2] must be a finite number (got null)"},
        {"cone past 90 degrees", [](json& j) { j["lights"][1]["outer_cone_deg"] = 120; },
         "s.json: lights[1].outer_cone_deg must be between 0 and 90 (got 120)"},
        {"inner wider than outer",
         [](json& j) {
             j["lights"][1]["inner_cone_deg"] = 40;
             j["lights"][1]["outer_cone_deg"] = 30;
         },
         "s.json: lights[1]: light parameter inner_cone_deg must not exceed outer_cone_deg (40.000000 > 30.000000)"},
        {"negative exposure", [](json& j) { j["pipeline"]["exposure"] = -1; },
         "s.json: pipeline.exposure must be between 0.05 and 16 (got -1)"},
        // The ranges of core/pipeline_fields.h, the same as the Pipeline panel's and the A/B table's.
        {"shininess past the panel's range", [](json& j) { j["pipeline"]["shininess"] = 1000; },
         "s.json: pipeline.shininess must be between 1 and 512 (got 1000)"},
        {"ambient above one",
         [](json& j) {
             j["pipeline"]["ambient"] = {0.1, 2.0, 0.1};
         },
         "s.json: pipeline.ambient[1] must be between 0 and 1 (got 2.0)"},
        {"the script's old name", [](json& j) { j["pipeline"]["cubes"] = true; },
         "s.json: pipeline.cubes is not a known field"},
        // out of range
        {"far before near", [](json& j) { j["camera"]["far"] = 0.001; },
         "s.json: camera.far must be greater than camera.near"},
        {"pitch past the pole", [](json& j) { j["camera"]["pitch_degrees"] = 90; },
         "s.json: camera.pitch_degrees must be between -89 and 89 (got 90)"},
        {"zoom out of range", [](json& j) { j["viewers"]["normal"]["zoom"] = 0.5; },
         "s.json: viewers.normal.zoom must be between 1 and 256 (got 0.5)"},
        {"empty remap range",
         [](json& j) { j["viewers"]["position"]["range_max"] = j["viewers"]["position"]["range_min"]; },
         "s.json: viewers.position.range_max must be greater than viewers.position.range_min"},
        {"light count", [](json& j) { j["scene"]["default_scene_lights"] = 262145; },
         "s.json: scene.default_scene_lights must be a whole number from 0 to 262144 (got 262145)"},
        // enums
        {"unknown mode", [](json& j) { j["pipeline"]["mode"] = "raytraced"; },
         "s.json: pipeline.mode must be one of quad, volumes, tiled, forward, clustered, forward+ or prepass (got "
         "\"raytraced\")"},
        {"unknown depth copy", [](json& j) { j["pipeline"]["depth_copy"] = "copy"; },
         "s.json: pipeline.depth_copy must be one of blit, shader or off (got \"copy\")"},
        // the depth copy's old key names the field as the file does, and is one field with the new one
        {"unknown blit",
         [](json& j) {
             j["pipeline"].erase("depth_copy");
             j["pipeline"]["blit"] = "copy";
         },
         "s.json: pipeline.blit must be one of blit, shader or off (got \"copy\")"},
        {"old and new key", [](json& j) { j["pipeline"]["blit"] = "off"; },
         "s.json: pipeline.blit is the old name of pipeline.depth_copy: give only one of them"},
        {"no depth copy", [](json& j) { j["pipeline"].erase("depth_copy"); }, "s.json: pipeline.depth_copy is missing"},
        {"enum by number", [](json& j) { j["pipeline"]["cull"] = 1; },
         "s.json: pipeline.cull must be one of back, front, none, flip or stencil (got a number)"},
        {"unknown normal display", [](json& j) { j["viewers"]["normal"]["normal_display"] = "signed"; },
         "s.json: viewers.normal.normal_display must be one of biased or absolute (got \"signed\")"},
        // viewer tools
        {"unknown colormap", [](json& j) { j["viewers"]["depth"]["tools"]["colormap"] = "jet"; },
         "s.json: viewers.depth.tools.colormap must be one of grey, turbo or viridis (got \"jet\")"},
        {"unknown overlay",
         [](json& j) {
             j["viewers"]["albedo"]["tools"]["overlays"] = {"nan", "zebra"};
         },
         "s.json: viewers.albedo.tools.overlays[1] must be one of nan, inf, negative or clip (got \"zebra\")"},
        {"overlays as bits", [](json& j) { j["viewers"]["albedo"]["tools"]["overlays"] = 3; },
         "s.json: viewers.albedo.tools.overlays must be an array of names out of nan, inf, negative or clip (got a "
         "number)"},
        {"histogram as text", [](json& j) { j["viewers"]["normal"]["tools"]["histogram"] = "yes"; },
         "s.json: viewers.normal.tools.histogram must be true or false (got a string)"},
        {"stencil on another viewer", [](json& j) { j["viewers"]["position"]["tools"]["stencil"] = true; },
         "s.json: viewers.position.tools.stencil must be false: only the depth viewer shows the stencil"},
        {"unknown tool", [](json& j) { j["viewers"]["depth"]["tools"]["zebra"] = true; },
         "s.json: viewers.depth.tools.zebra is not a known field"},
        {"sync as a number", [](json& j) { j["viewer_tools"]["sync"] = 1; },
         "s.json: viewer_tools.sync must be true or false (got a number)"},
        {"viewport zoom out of range", [](json& j) { j["viewer_tools"]["viewport"]["viewer"]["zoom"] = 0; },
         "s.json: viewer_tools.viewport.viewer.zoom must be between 1 and 256 (got 0)"},
        {"viewport stencil", [](json& j) { j["viewer_tools"]["viewport"]["viewer"]["tools"]["stencil"] = true; },
         "s.json: viewer_tools.viewport.viewer.tools.stencil must be false: only the depth viewer shows the stencil"},
        // versions and format
        {"newer version", [](json& j) { j["version"] = 2; },
         "s.json: version 2 is not supported; this program reads version 1 (the file comes from a newer gbuffer-lab)"},
        {"older version", [](json& j) { j["version"] = 0; },
         "s.json: version 0 is not supported; this program reads version 1"},
        {"version as text", [](json& j) { j["version"] = "1"; }, "s.json: version must be a whole number (got \"1\")"},
        {"another format", [](json& j) { j["format"] = "blender-scene"; },
         "s.json: format must be \"gbuffer-lab-session\" (got \"blender-scene\"); this is not a gbuffer-lab session"},
        // a newer file's new fields do not hide its version
        {"newer version with new fields",
         [](json& j) {
             j["version"] = 3;
             j["shadows"] = true;
         },
         "s.json: version 3 is not supported; this program reads version 1 (the file comes from a newer gbuffer-lab)"},
        {"not an object",
         [](json& j) {
             j = json::array({1, 2});
         },
         "s.json: the file must hold a JSON object (got an array)"},
    };
    for (auto const& c : cases) {
        json j = json::parse(sessionToJson(richSession()));
        c.edit(j);
        SessionLoad const r = parseSession(j.dump(2), "s.json");
        EXPECT_FALSE(r.session) << c.what;
        EXPECT_EQ(r.error, c.message) << c.what;
    }
}

TEST(Session, TooManyLightsAreRefusedWithTheLimit) {
    Session s;
    s.lights.assign(std::size_t(kMaxLights) + 1, PointLight{});
    SessionLoad const r = parseSession(sessionToJson(s), "big.json");
    EXPECT_FALSE(r.session);
    EXPECT_EQ(r.error, "big.json: lights holds 262145 lights; the limit is 262144");
    s.lights.resize(std::size_t(kMaxLights));
    SessionLoad const ok = parseSession(sessionToJson(s), "big.json");
    ASSERT_TRUE(ok.session) << ok.error;
    EXPECT_EQ(ok.session->lights.size(), std::size_t(kMaxLights));
}

TEST(Session, TextThatIsNotJsonNamesTheFileAndPlace) {
    for (std::string const text : {"", "{", "{\"format\": \"gbuffer-lab-session\", \"version\": 1,}", "{\"kq\": NaN}",
                                   "{\"kq\": 1e999}", "\xff\xfe"}) {
        SessionLoad const r = parseSession(text, "broken.json");
        EXPECT_FALSE(r.session) << text;
        EXPECT_EQ(r.error.rfind("broken.json: not valid JSON: ", 0), 0u) << r.error;
        EXPECT_EQ(r.error.find("[json.exception"), std::string::npos) << r.error;
    }
}

TEST(Session, EveryTruncationAndByteFlipFailsCleanly) {
    // Whatever a crash or a stray editor leaves in the file, parsing ends with a message or a
    // valid session, never a crash (ASan/UBSan runs check the "never").
    std::string const text = sessionToJson(richSession());
    // Every prefix up to the closing brace (the text ends in "}\n"; without the newline it is whole).
    ASSERT_EQ(text.substr(text.size() - 2), "}\n");
    for (std::size_t n = 0; n < text.size() - 1; n += 7) {
        SessionLoad const r = parseSession(std::string_view(text).substr(0, n), "t.json");
        EXPECT_FALSE(r.session) << n;
        EXPECT_FALSE(r.error.empty());
    }
    int accepted = 0;
    for (std::size_t i = 0; i < text.size(); i += 5) {
        for (char c : {'\0', '-', '9', '"', '}', 'e'}) {
            std::string t = text;
            t[i] = c;
            SessionLoad const r = parseSession(t, "t.json");
            EXPECT_NE(bool(r.session), !r.error.empty());
            accepted += bool(r.session);
        }
    }
    // Some flips stay valid (a digit for a digit); most must not.
    EXPECT_GT(accepted, 0);
}

TEST(Session, MissingFileAndDirectoryAreMessages) {
    std::string const dir = test::freshTempDir("session_missing");
    SessionLoad const a = loadSession(dir + "/nope.json");
    EXPECT_FALSE(a.session);
    EXPECT_NE(a.error.find(dir + "/nope.json"), std::string::npos) << a.error;
    SessionLoad const b = loadSession(dir);
    EXPECT_FALSE(b.session);
    EXPECT_NE(b.error.find("is a directory"), std::string::npos) << b.error;
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
