// `gbuffer-lab bench` end to end: a tiny run's JSON, and bad arguments.
#include "run_command.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <algorithm>

using gbl::test::runGbufferLab;

TEST(BenchCommand, TinyRunReportsEveryCombination) {
    std::string const dir = gbl::test::freshTempDir("bench_tiny");
    std::string const json = dir + "/bench.json";
    auto const r = runGbufferLab({"bench", "--size", "64x36", "--lights", "4,8", "--modes", "quad,volumes,forward",
                                  "--frames", "2", "--warmup", "1", "--json", json});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto const doc = gbl::test::readJsonFile(json);
    ASSERT_TRUE(doc.contains("combinations")) << doc.dump(2);
    auto const& results = doc["combinations"];
    ASSERT_EQ(results.size(), 6u) << "2 light counts x 3 modes";
    for (auto const& res : results) {
        EXPECT_EQ(res["status"], "ok") << res.dump();
        EXPECT_EQ(res["frames_measured"], 2) << res.dump();
        EXPECT_EQ(res["gl_errors"], 0) << res.dump();
        double const median = res["frame"]["median_ms"].get<double>();
        // Positive, and bounded by the wall time the whole combination took.
        EXPECT_GT(median, 0.0) << res.dump();
        EXPECT_LE(median, res["wall_seconds"].get<double>() * 1000.0) << res.dump();
        EXPECT_LE(res["lights_shaded"].get<int>(), res["lights"].get<int>());
    }
    EXPECT_NE(r.output.find("volumes"), std::string::npos) << "the table names the modes:\n" << r.output;
}

// The lists' names come from the pipeline field table: a name outside it is one sentence listing them.
TEST(BenchCommand, AnUnknownNameInAListNamesTheValidOnes) {
    struct Case {
        std::vector<std::string> args;
        std::string expect;
    };
    for (Case const& c : std::vector<Case>{
             {{"bench", "--modes", "quad,raytraced"},
              "--modes: 'raytraced' is not one of quad, volumes, tiled, forward, clustered, forward+ or prepass"},
             {{"bench", "--cull", "front,up"}, "--cull: 'up' is not one of back, front, none, flip or stencil"},
             {{"bench", "--layouts", "classic,zip"},
              "--layouts: 'zip' is not one of classic, packed, naive8 or rgb10a2"},
         }) {
        auto const r = gbl::test::expectRefused(c.args, c.expect);
        EXPECT_LE(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    }
}

TEST(BenchCommand, BadArgumentsExitWithCodeTwo) {
    std::vector<std::vector<std::string>> const cases{
        {"bench", "--modes", "raytraced"},
        {"bench", "--lights", "300000"},  // over kMaxLights (262,144)
        {"bench", "--size", "0x0"},
        {"bench", "--frames", "0"},
        {"bench", "--radius-scale", "-1"},
        {"bench", "--scene", "/nonexistent/scene.gltf"},
        {"bench", "--scene", "a.gltf", "--session", "b.json"},
    };
    for (auto const& args : cases) {
        auto const r = runGbufferLab(args);
        EXPECT_EQ(r.exitCode, 2) << args[1] << " " << args[2] << "\n" << r.output;
        EXPECT_FALSE(r.output.empty());
    }
}
