// `gbuffer-lab lessons` and `render --lesson`: the list, a step rendered with the same files as
// `render` plus its checked claim, and one-sentence refusals with exit code 2.
#include "run_command.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

using namespace gbl::test;
namespace fs = std::filesystem;

namespace {

TEST(LessonsCli, ListsEveryLessonAndItsSteps) {
    CommandResult const r = runGbufferLab({"lessons", "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    nlohmann::json const list = nlohmann::json::parse(r.output);
    ASSERT_GE(list.size(), 10u);
    bool found = false;
    for (auto const& l : list) {
        EXPECT_GE(l["steps"].size(), 3u) << l["id"];
        if (l["id"] == "camera_inside") {
            found = true;
            EXPECT_EQ(l["steps"][1]["step"], 2);
            EXPECT_EQ(l["steps"][1]["claim"], "loses_light");
        }
    }
    EXPECT_TRUE(found);
    CommandResult const text = runGbufferLab({"lessons"});
    ASSERT_EQ(text.exitCode, 0);
    EXPECT_NE(text.output.find("camera_inside:2  Cull back loses the light"), std::string::npos) << text.output;
}

TEST(LessonsCli, RendersAStepWithTheRenderFilesAndItsClaim) {
    std::string const out = freshTempDir("lesson_render");
    CommandResult const r = runGbufferLab({"render", "--lesson", "camera_inside:2", "--out", out});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (char const* f : {"final.png", "lighting.exr", "position.exr", "depth.exr", "stats.json", "lights.json",
                          "camera.json", "claim.json"})
        EXPECT_TRUE(fs::exists(fs::path(out) / f)) << f;
    nlohmann::json const claim = readJsonFile(out + "/claim.json");
    EXPECT_EQ(claim["lesson"], "camera_inside");
    EXPECT_EQ(claim["step"], 2);
    EXPECT_EQ(claim["claim"], "loses_light");
    EXPECT_TRUE(claim["holds"].get<bool>()) << claim["detail"];
    nlohmann::json const stats = readJsonFile(out + "/stats.json");
    EXPECT_EQ(stats["width"], 480);  // the lesson's own size
    // --size overrides the lesson's size.
    CommandResult const small = runGbufferLab({"render", "--lesson", "gbuffer", "--size", "320x180", "--out", out});
    ASSERT_EQ(small.exitCode, 0) << small.output;
    EXPECT_EQ(readJsonFile(out + "/stats.json")["width"], 320);
}

TEST(LessonsCli, RefusesBadLessonsInOneSentence) {
    std::string const out = freshTempDir("lesson_refuse");
    expectRefused({"render", "--lesson", "nosuch", "--out", out}, "--lesson: no lesson has the id \"nosuch\"");
    expectRefused({"render", "--lesson", "gbuffer:9", "--out", out}, "lesson gbuffer has steps 1 to 5, not \"9\"");
    expectRefused({"render", "--lesson", "gbuffer", "--mode", "tiled", "--out", out},
                  "--mode cannot be combined with --lesson");
    std::string const dir = freshTempDir("lesson_bad_dir");
    std::ofstream(dir + "/broken.json") << R"({"format": "gbuffer-lab-lesson", "version": 2, "id": "b", "title": "B",
              "steps": [{"title": "t", "look": "l", "equation": "e", "question": "q", "answer": "a", "pipeline": {"cull": "up"}}]})";
    std::string const file = dir + "/broken.json";
    expectRefused({"render", "--lesson", "b", "--lessons-dir", dir, "--out", out},
                  file + ": steps[0].pipeline.cull must be one of back, front, none, flip or stencil (got \"up\")");
    CommandResult const list = runGbufferLab({"lessons", "--lessons-dir", dir});
    EXPECT_EQ(list.exitCode, 2);
    EXPECT_NE(list.output.find(file + ": steps[0].pipeline.cull"), std::string::npos) << list.output;
}

}  // namespace
