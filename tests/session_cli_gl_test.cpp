// Sessions on the command line: a saved session renders the same frame again, a session's
// values are really used, bad sessions and requests past the limits exit 2 with the limit.
#include "image/image_io.h"
#include "run_command.h"
#include "session/session.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>

using namespace gbl;
using gbl::test::runGbufferLab;
namespace fs = std::filesystem;

namespace {

// Largest absolute difference of any channel of any pixel; -1 for different sizes.
float maxDifference(std::string const& a, std::string const& b) {
    auto const x = readImage(a), y = readImage(b);
    if (!x || !y) return -2.0f;
    if (x->width != y->width || x->height != y->height || x->channels != y->channels) return -1.0f;
    float m = 0.0f;
    for (std::size_t i = 0; i < x->pixels.size(); ++i) m = std::max(m, std::abs(x->pixels[i] - y->pixels[i]));
    return m;
}

}  // namespace

TEST(SessionCli, SavedSessionReproducesTheSameFrame) {
    ASSERT_TRUE(fs::exists(test::binaryPath())) << test::binaryPath();
    std::string const dir = test::freshTempDir("session_cli_same");
    std::string const a = dir + "/a", b = dir + "/b", session = dir + "/frame.json";
    // Non-default everything the command line can set, so a value the session forgets shows.
    auto const first =
        runGbufferLab({"render", "--out", a, "--size", "192x108", "--lights", "12", "--time", "3.5", "--mode",
                       "volumes", "--cull", "back", "--depth-copy", "shader", "--save-session", session});
    ASSERT_EQ(first.exitCode, 0) << first.output;
    ui::SessionLoad const saved = ui::loadSession(session);
    ASSERT_TRUE(saved.session) << saved.error;
    EXPECT_EQ(saved.session->scene, "default");
    EXPECT_EQ(saved.session->lights.size(), 12u);
    EXPECT_EQ(saved.session->pipeline.mode, LightingMode::Volumes);
    EXPECT_EQ(saved.session->pipeline.cull, CullMode::Back);
    EXPECT_EQ(saved.session->pipeline.depthCopy, DepthCopy::Shader);
    EXPECT_FLOAT_EQ(saved.session->animation.time, 3.5f);

    auto const second = runGbufferLab({"render", "--out", b, "--size", "192x108", "--session", session});
    ASSERT_EQ(second.exitCode, 0) << second.output;
    // Pixel-identical: same scene, camera, lights and settings through the same deterministic
    // renderer on the same driver. Any difference means the session lost or changed a value.
    for (char const* f : {"final.png", "lighting.exr", "position.exr", "depth.exr"})
        EXPECT_EQ(maxDifference(a + "/" + f, b + "/" + f), 0.0f) << f;
    EXPECT_EQ(test::readJsonFile(a + "/lights.json"), test::readJsonFile(b + "/lights.json"));
    auto const stats = test::readJsonFile(b + "/stats.json");
    EXPECT_EQ(stats["mode"], "volumes");
    EXPECT_EQ(stats["cull"], "back");
    EXPECT_EQ(stats["depth_copy"], "shader");
    EXPECT_EQ(stats["gl_errors"], 0);
}

TEST(SessionCli, TheSessionsValuesAreWhatGetsRendered) {
    // Edit the saved session (as the editor would) and check the frame follows it: otherwise
    // the test above could pass by ignoring the session and using the same defaults.
    std::string const dir = test::freshTempDir("session_cli_used");
    std::string const session = dir + "/s.json";
    ASSERT_EQ(
        runGbufferLab({"render", "--out", dir + "/a", "--size", "160x90", "--lights", "8", "--save-session", session})
            .exitCode,
        0);
    ui::Session s = *ui::loadSession(session).session;
    for (auto& l : s.lights) l.intensity *= 4.0f;
    s.lights[0].name = "edited";
    s.camera.yawDegrees += 30.0f;
    s.pipeline.view = DebugView::Normal;
    ASSERT_EQ(ui::saveSession(session, s), std::nullopt);
    auto const r = runGbufferLab({"render", "--out", dir + "/b", "--size", "160x90", "--session", session});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_GT(maxDifference(dir + "/a/final.png", dir + "/b/final.png"), 0.1f);
    EXPECT_GT(maxDifference(dir + "/a/position.exr", dir + "/b/position.exr"), 0.1f);  // the camera moved
    auto const lights = test::readJsonFile(dir + "/b/lights.json");
    ASSERT_EQ(lights.size(), 8u);
    EXPECT_EQ(lights[0]["name"], "edited");
    EXPECT_FLOAT_EQ(lights[1]["intensity"].get<float>(), s.lights[1].intensity);
}

TEST(SessionCli, OptionsOnTheCommandLineOverrideTheSession) {
    std::string const dir = test::freshTempDir("session_cli_override");
    std::string const session = dir + "/s.json";
    ASSERT_EQ(runGbufferLab(
                  {"render", "--out", dir + "/a", "--size", "96x54", "--mode", "volumes", "--save-session", session})
                  .exitCode,
              0);
    auto const r = runGbufferLab(
        {"render", "--out", dir + "/b", "--size", "96x54", "--session", session, "--mode", "quad", "--blit", "off"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto const stats = test::readJsonFile(dir + "/b/stats.json");
    EXPECT_EQ(stats["mode"], "quad");
    EXPECT_EQ(stats["depth_copy"], "off");  // given as --blit, the option's old name
    EXPECT_EQ(stats["cull"], "front");      // from the session
}

TEST(SessionCli, BadSessionsExitTwoWithOneSentenceNamingTheField) {
    std::string const dir = test::freshTempDir("session_cli_bad");
    std::string const good = dir + "/good.json";
    ASSERT_EQ(runGbufferLab({"render", "--out", dir + "/a", "--size", "64x36", "--lights", "4", "--save-session", good})
                  .exitCode,
              0);
    auto j = test::readJsonFile(good);
    j["lights"][3]["kq"] = -1.0;
    std::string const bad = dir + "/bad.json";
    std::ofstream(bad) << j.dump(2);
    struct Case {
        std::vector<std::string> args;
        std::string expect;
    };
    std::vector<Case> const cases{
        {{"render", "--out", dir + "/b", "--session", bad},
         bad + ": lights[3].kq must be a finite number >= 0 (got -1.0)"},
        {{"render", "--out", dir + "/b", "--session", dir + "/missing.json"}, dir + "/missing.json"},
        {{"render", "--out", dir + "/b", "--session", good, "--lights", "3"}, "cannot be combined with --session"},
        {{"render", "--out", dir + "/b", "--session", good, "--save-session", "/proc/x/s.json"}, "/proc/x/s.json"},
    };
    for (auto const& c : cases) {
        auto const r = runGbufferLab(c.args);
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_NE(r.output.find(c.expect), std::string::npos) << r.output;
        EXPECT_LE(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    }
}

TEST(SessionCli, SessionWithMoreLightsThanTheLimitIsRefused) {
    std::string const dir = test::freshTempDir("session_cli_many");
    ui::Session s;
    s.lights.assign(std::size_t(kMaxLights) + 1, PointLight{});
    std::string const path = dir + "/many.json";
    ASSERT_EQ(ui::saveSession(path, s), std::nullopt);
    auto const r = runGbufferLab({"render", "--out", dir + "/o", "--size", "64x36", "--session", path});
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("the limit is 262144"), std::string::npos) << r.output;
}

TEST(Limits, RequestsPastTheLimitsExitTwoStatingTheLimit) {
    // render's own limits are covered by render_cli_gl_test; these are the other entry points.
    // All are refused before a window or context is made, so they cannot hang or run out of memory.
    std::string const dir = test::freshTempDir("limits");
    struct Case {
        std::vector<std::string> args;
        std::string expect;
    };
    std::vector<Case> const cases{
        {{"bench", "--size", "20000x20000"}, "16384"},
        {{"bench", "--lights", "300000"}, "262144"},
        {{"bench", "--lights", "32,300000"}, "262144"},
        {{"--size", "20000x20000"}, "16384"},
        {{"--lights", "300000"}, "262144"},
        {{"render", "--out", dir, "--size", "16385x10"}, "16384"},
    };
    for (auto const& c : cases) test::expectRefused(c.args, c.expect);
}
