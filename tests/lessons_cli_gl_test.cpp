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
    EXPECT_NE(text.output.find("camera_inside:2  Another cull mode from inside"), std::string::npos) << text.output;
}

// The JSON list carries each step's tasks and prediction in the lesson file's own vocabulary, so
// tools (and the browser build) read what the editor checks.
TEST(LessonsCli, JsonListsTasksAndPredictions) {
    CommandResult const r = runGbufferLab({"lessons", "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    nlohmann::json const list = nlohmann::json::parse(r.output);
    auto lesson = [&](std::string const& id) -> nlohmann::json {
        for (auto const& l : list)
            if (l["id"] == id) return l;
        ADD_FAILURE() << "no lesson " << id;
        return nlohmann::json::object();
    };
    nlohmann::json const attenuation = lesson("attenuation");
    ASSERT_GE(attenuation["steps"].size(), 2u);
    nlohmann::json const& step1 = attenuation["steps"][0];
    ASSERT_EQ(step1["tasks"].size(), 1u) << step1.dump(2);
    nlohmann::json const& task = step1["tasks"][0];
    EXPECT_EQ(task["kind"], "light_field");
    EXPECT_EQ(task["light"], 0);
    EXPECT_EQ(task["field"], "radius");
    EXPECT_DOUBLE_EQ(task["value"].get<double>(), 5.0);
    EXPECT_DOUBLE_EQ(task["tolerance"].get<double>(), 0.2);  // written with a float's digits, not 0.2000000029
    EXPECT_EQ(task["only_changed"], nlohmann::json::parse(R"(["kq"])"));
    EXPECT_NE(task["goal"].get<std::string>().find("changing only Kq"), std::string::npos) << task["goal"];
    EXPECT_NE(task["hint"].get<std::string>().find("Lights window"), std::string::npos) << task["hint"];
    EXPECT_FALSE(step1.contains("predict"));
    EXPECT_FALSE(step1["answer"].get<std::string>().empty());
    // A setting task's value is the setting's name for it, as in the file.
    nlohmann::json const blit = lesson("depth_blit")["steps"][3]["tasks"][0];
    EXPECT_EQ(blit["kind"], "setting");
    EXPECT_EQ(blit["setting"], "depth_copy");  // the lesson file's "blit" is the field's old name
    EXPECT_EQ(blit["value"], "off");
    EXPECT_FALSE(blit.contains("tolerance"));
    nlohmann::json const scale = lesson("light_volumes")["steps"][1]["tasks"][0];
    EXPECT_DOUBLE_EQ(scale["value"].get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(scale["tolerance"].get<double>(), 0.005);
    // Predictions: a number one and a multiple-choice one, with their answers.
    nlohmann::json const& number = attenuation["steps"][1]["predict"];
    EXPECT_DOUBLE_EQ(number["number"].get<double>(), 5.18);
    EXPECT_DOUBLE_EQ(number["tolerance"].get<double>(), 0.4);
    EXPECT_FALSE(number.contains("choices"));
    EXPECT_FALSE(number["explain"].get<std::string>().empty());
    nlohmann::json const choice = lesson("camera_inside")["steps"][1]["predict"];
    EXPECT_EQ(choice["choices"].size(), 3u);
    EXPECT_EQ(choice["correct"], 0);
    EXPECT_EQ(choice["before"]["pipeline"]["cull"], "front");
    EXPECT_TRUE(lesson("gbuffer")["steps"][0]["tasks"].empty());
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

// `render --lesson --size` checks the claim on the student's frame (the editor's viewport at 1280x720
// is 641x407): executed_vs_lit:1's frame-wide share of wasted evaluations holds there, and
// claim.json says what was measured on that frame.
TEST(LessonsCli, ChecksTheClaimOnTheStudentsFrameSize) {
    std::string const out = freshTempDir("lesson_student_size");
    CommandResult const r =
        runGbufferLab({"render", "--lesson", "executed_vs_lit:1", "--size", "641x407", "--out", out});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(readJsonFile(out + "/stats.json")["width"], 641);
    nlohmann::json const claim = readJsonFile(out + "/claim.json");
    EXPECT_EQ(claim["claim"], "executed_exceeds_lit");
    EXPECT_TRUE(claim["holds"].get<bool>()) << claim["detail"];
    std::string const detail = claim["detail"];
    EXPECT_NE(detail.find("over the frame"), std::string::npos) << detail;
    EXPECT_NE(detail.find("(range 85 .. 93 %)"), std::string::npos) << detail;
    EXPECT_NE(r.output.find("641x407"), std::string::npos) << r.output;
}

// A lesson on a glTF scene of the shared models: `render --lesson` loads the scene, not the default
// one, and checks the step's claim on it; a lesson naming a missing file is one sentence naming
// `scene`, and the other lessons of the folder still list.
TEST(LessonsCli, ALessonOnAGltfSceneRendersThatScene) {
    std::string const box = sharedGltfDir() + "/Box/Box.gltf";
    if (!fs::exists(box)) GTEST_SKIP() << "needs the shared models: " << box << " is absent";
    std::string const dir = freshTempDir("lesson_gltf_dir");
    nlohmann::json lesson = nlohmann::json::parse(R"({
      "format": "gbuffer-lab-lesson", "version": 2, "id": "box", "title": "Box", "scene": "Box/Box.gltf",
      "size": [320, 180],
      "setup": {"lights": [{"position": [1.5, 2, 2], "color": [1, 1, 1], "intensity": 2,
                            "kc": 1, "kl": 0.35, "kq": 0.44, "threshold": 0.01953125}],
                "camera": {"position": [2, 1.5, 2.5], "look_at": [0, 0, 0]}},
      "steps": [{"title": "The box lit", "look": "l", "equation": "{pixel.lit}", "question": "q?", "answer": "a.",
                 "pixel": [0.5, 0.5], "claim": {"kind": "matches_cpu"}}]})");
    std::ofstream(dir + "/box.json") << lesson.dump();
    std::string const out = freshTempDir("lesson_gltf_out");
    CommandResult const r = runGbufferLab({"render", "--lesson", "box:1", "--lessons-dir", dir, "--out", out});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    nlohmann::json const stats = readJsonFile(out + "/stats.json");
    EXPECT_EQ(stats["triangles"], 12);  // the Box model's 6 faces, not the default scene
    EXPECT_EQ(stats["lights"], 1);
    EXPECT_EQ(stats["width"], 320);
    nlohmann::json const claim = readJsonFile(out + "/claim.json");
    EXPECT_EQ(claim["claim"], "matches_cpu");
    EXPECT_TRUE(claim["holds"].get<bool>()) << claim["detail"];
    CommandResult const list = runGbufferLab({"lessons", "--json", "--lessons-dir", dir});
    ASSERT_EQ(list.exitCode, 0) << list.output;
    EXPECT_TRUE(fs::equivalent(nlohmann::json::parse(list.output)[0]["scene"].get<std::string>(), box));

    lesson["id"] = "gone";
    lesson["scene"] = "Box/NoSuchBox.gltf";
    std::ofstream(dir + "/gone.json") << lesson.dump();
    CommandResult const listed = runGbufferLab({"lessons", "--lessons-dir", dir});
    EXPECT_EQ(listed.exitCode, 2);
    EXPECT_NE(listed.output.find(dir + "/gone.json: scene \"Box/NoSuchBox.gltf\" is not a file"), std::string::npos)
        << listed.output;
    EXPECT_NE(listed.output.find("box:1  The box lit"), std::string::npos) << listed.output;
}

// forward_vs_deferred:3 says its one light lights the pixel (`reached`: 1): the claim holds there,
// and fails on a pixel of the same frame the light does not reach.
TEST(LessonsCli, TheReachedCountIsCheckedOnTheFrame) {
    std::string const out = freshTempDir("lesson_reached_out");
    CommandResult const shipped = runGbufferLab({"render", "--lesson", "forward_vs_deferred:3", "--out", out});
    ASSERT_EQ(shipped.exitCode, 0) << shipped.output;
    nlohmann::json const holds = readJsonFile(out + "/claim.json");
    EXPECT_TRUE(holds["holds"].get<bool>()) << holds["detail"];
    EXPECT_NE(holds["detail"].get<std::string>().find("1 of 1 lights reach the pixel"), std::string::npos)
        << holds["detail"];

    nlohmann::json lesson = readJsonFile(sourcePath("assets/lessons/10_forward_vs_deferred.json"));
    lesson["steps"][2]["pixel"] = {0.2, 0.45};  // the far left of the court, outside the light's radius
    std::string const dir = freshTempDir("lesson_reached_dir");
    std::ofstream(dir + "/fvd.json") << lesson.dump();
    CommandResult const moved =
        runGbufferLab({"render", "--lesson", "forward_vs_deferred:3", "--lessons-dir", dir, "--out", out});
    ASSERT_EQ(moved.exitCode, 0) << moved.output;
    nlohmann::json const fails = readJsonFile(out + "/claim.json");
    EXPECT_FALSE(fails["holds"].get<bool>()) << fails["detail"];
    EXPECT_NE(fails["detail"].get<std::string>().find("0 of 1 lights reach the pixel (the step says 1)"),
              std::string::npos)
        << fails["detail"];
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
