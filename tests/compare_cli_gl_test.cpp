// `gbuffer-lab compare` and `render --accumulate` end to end: the files they write, their values,
// and the inputs they refuse.
#include "image/image_io.h"
#include "run_command.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace gbl;
using gbl::test::runGbufferLab;
namespace fs = std::filesystem;

namespace {

// A session saved by `render --save-session` with the given extra render options.
std::string savedSession(std::string const& dir, std::string const& name, std::vector<std::string> extra) {
    std::string const session = dir + "/" + name + ".json";
    std::vector<std::string> args{"render",   "--out", dir + "/r_" + name, "--size", "64x36",
                                  "--lights", "8",     "--save-session",   session};
    args.insert(args.end(), extra.begin(), extra.end());
    auto const r = runGbufferLab(args);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return session;
}

double maxAbs(FloatImage const& a, FloatImage const& b) {
    double m = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        if (i % std::size_t(a.channels) < 3) m = std::max(m, double(std::abs(a.pixels[i] - b.pixels[i])));
    return m;
}

}  // namespace

TEST(CompareCommand, SameSessionsDoNotDifferAndEveryFileIsWritten) {
    std::string const dir = test::freshTempDir("compare_same");
    std::string const a = savedSession(dir, "a", {});
    auto const r = runGbufferLab({"compare", a, a, "--out", dir + "/out", "--size", "96x54"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (char const* f : {"a/final.png", "a/lighting.exr", "a/stats.json", "b/final.png", "b/lighting.exr", "diff.exr",
                          "diff.png", "compare.json"})
        EXPECT_TRUE(fs::exists(fs::path(dir) / "out" / f)) << f;
    auto const j = test::readJsonFile(dir + "/out/compare.json");
    EXPECT_EQ(j["width"], 96);
    EXPECT_EQ(j["max_abs"].get<double>(), 0.0);  // the same frame twice is bit-identical
    EXPECT_EQ(j["pixels_differing"], 0);
    EXPECT_EQ(j["pixels"], 96 * 54);
    EXPECT_EQ(j["nan_a"], 0);
    EXPECT_EQ(j["nan_b"], 0);
    EXPECT_GT(j["threshold"].get<double>(), 0.0);
    for (char const* side : {"gpu_ms_a", "gpu_ms_b"})
        for (char const* pass : {"geometry", "lighting", "display", "total"})
            EXPECT_TRUE(j[side].contains(pass)) << side << " " << pass;
}

TEST(CompareCommand, DifferentSettingsDifferWhereTheLightingChanged) {
    std::string const dir = test::freshTempDir("compare_diff");
    std::string const a = savedSession(dir, "a", {"--mode", "quad"});
    // The camera inside no volume, but `none` shades every covered pixel once per face: brighter.
    std::string const b = savedSession(dir, "b", {"--mode", "volumes", "--cull", "none"});
    auto const r = runGbufferLab({"compare", a, b, "--out", dir + "/out", "--size", "96x54"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto const j = test::readJsonFile(dir + "/out/compare.json");
    auto const la = readImage(dir + "/out/a/lighting.exr"), lb = readImage(dir + "/out/b/lighting.exr");
    auto const diff = readImage(dir + "/out/diff.exr");
    ASSERT_TRUE(la && lb && diff);
    // compare.json's max is the largest RGB difference of the two lit frames it wrote.
    EXPECT_NEAR(j["max_abs"].get<double>(), maxAbs(*la, *lb), 1e-6);
    EXPECT_GT(j["max_abs"].get<double>(), 0.01);
    EXPECT_GT(j["pixels_differing"].get<long>(), 0);
    EXPECT_EQ(diff->channels, 1);
    EXPECT_EQ(diff->width, 96);
    int const mx = j["max_at"][0], my = j["max_at"][1];
    EXPECT_NEAR(diff->at(mx, my, 0), j["max_abs"].get<double>(), 1e-6);
    EXPECT_GT(j["mean_abs"].get<double>(), 0.0);
    EXPECT_LT(j["mean_abs"].get<double>(), j["max_abs"].get<double>());
}

TEST(CompareCommand, RefusesDifferentScenesAndBadFiles) {
    std::string const dir = test::freshTempDir("compare_bad");
    std::string const a = savedSession(dir, "a", {});
    std::string const gltf = savedSession(dir, "g", {});
    // The same session pointing at a glTF scene instead.
    nlohmann::json j = test::readJsonFile(gltf);
    j["scene"]["source"] = (fs::path(test::dataDir()) / "gltf/triangle.gltf").string();
    std::ofstream(gltf) << j.dump(2);
    test::expectRefused({"compare", a, gltf, "--out", dir + "/out"}, "different scenes");
    test::expectRefused({"compare", a, dir + "/missing.json", "--out", dir + "/out"}, "missing.json");
    test::expectRefused({"compare", a, a, "--out", dir + "/out", "--size", "0x5"}, "size");
}

TEST(RenderAccumulate, ZeroIsTheFrameWithoutLightsAndTheRangeIsChecked) {
    std::string const dir = test::freshTempDir("render_accumulate");
    auto r = runGbufferLab({"render", "--out", dir + "/k0", "--size", "96x54", "--accumulate", "0"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("first 0 accumulated"), std::string::npos) << r.output;
    r = runGbufferLab({"render", "--out", dir + "/none", "--size", "96x54", "--lights", "0"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = runGbufferLab({"render", "--out", dir + "/k4", "--size", "96x54", "--accumulate", "4"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto const k0 = readImage(dir + "/k0/lighting.exr"), none = readImage(dir + "/none/lighting.exr");
    auto const k4 = readImage(dir + "/k4/lighting.exr");
    ASSERT_TRUE(k0 && none && k4);
    EXPECT_EQ(maxAbs(*k0, *none), 0.0);  // ambient alone, as with no lights at all
    EXPECT_GT(maxAbs(*k4, *k0), 0.01);   // four lights (and light 4's outline) add light
    test::expectRefused({"render", "--out", dir + "/x", "--size", "96x54", "--accumulate", "33"}, "32 lights");
    test::expectRefused({"render", "--out", dir + "/x", "--accumulate", "-1"}, "--accumulate");
    test::expectRefused({"render", "--out", dir + "/x", "--contribution"}, "--accumulate");
}
