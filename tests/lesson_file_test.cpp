// Lesson files on the CPU: a valid lesson reads with the session code's rules, broken ones give
// one message naming the field (claims, A/B, scenes, a broken file among others), old names still
// load, step references, saving a step, lessons on a glTF scene. What the shipped steps say and what
// a step does in the editor: lesson_steps_test.
#include "session/lesson_file.h"
#include "lesson_samples.h"
#include "model/lesson_claims.h"
#include "run_command.h"
#include "scene/default_scene.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>

#include <stdlib.h>

using namespace gbl;
using namespace gbl::ui;
using gbl::test::lessonError;
using gbl::test::minimalLesson;
using nlohmann::json;

namespace {

TEST(LessonFile, AValidLessonReadsEveryField) {
    LessonLoad const l = parseLesson(minimalLesson().dump(), "demo.json");
    ASSERT_TRUE(l.lesson) << l.error;
    ASSERT_EQ(l.lesson->steps.size(), 1u);
    LessonStep const& s = l.lesson->steps[0];
    EXPECT_EQ(s.state.pipeline.mode, LightingMode::Volumes);  // from the setup
    EXPECT_EQ(s.state.pipeline.cull, CullMode::Back);         // from the step
    EXPECT_EQ(s.state.pipeline.volumeScale, 0.5f);
    EXPECT_EQ(s.state.lights, makeDefaultLights(4));
    EXPECT_EQ(s.defaultSceneLights, 4);
    EXPECT_EQ(s.state.selectedLight, 2);
    EXPECT_EQ(s.state.activeViewer, int(ViewerKind::Depth));
    ASSERT_TRUE(s.state.pixel);
    EXPECT_EQ(*s.state.pixel, glm::vec2(0.25f, 0.75f));
    // look_at: the camera faces the origin from (0, 4, 8).
    glm::vec3 const want = glm::normalize(glm::vec3(0, -4, -8));
    EXPECT_NEAR(glm::dot(s.state.camera.forward(), want), 1.0f, 1e-5f);
    ASSERT_TRUE(s.claim);
    EXPECT_EQ(s.claim->kind, ClaimKind::LosesLight);
    EXPECT_EQ(s.claim->light, 1);
    ASSERT_TRUE(s.claim->reference);
    EXPECT_EQ(s.claim->reference->cull, CullMode::Front);
    EXPECT_EQ(s.claim->reference->mode, LightingMode::Volumes);  // the step's pipeline, one setting changed
    EXPECT_EQ(s.claim->reference->volumeScale, 0.5f);
}

TEST(LessonFile, BrokenFilesNameTheField) {
    EXPECT_NE(parseLesson("{\"format\": ", "bad.json").error.find("bad.json: not valid JSON"), std::string::npos);
    struct Case {
        std::function<void(json&)> breakIt;
        std::string expect;
    };
    std::vector<Case> const cases{
        {[](json& j) { j["version"] = 3; }, "demo.json: version 3 is not supported"},
        {[](json& j) { j["steps"][0]["claim"]["reached"] = 1; },
         "demo.json: steps[0].claim.reached is not a field of a loses_light claim"},
        {[](json& j) { j["steps"][0]["claim"]["bound"] = 0.1; },  // same_image's, not loses_light's
         "demo.json: steps[0].claim.bound is not a field of a loses_light claim"},
        {[](json& j) {
             j["steps"][0]["claim"] = {{"kind", "matches_cpu"}, {"reached", 5}};
         },
         "demo.json: steps[0].claim.reached must be a whole number from 0 to 4 (got 5)"},
        {[](json& j) { j["version"] = 1; },
         "demo.json: version 1 is not supported; this program reads lesson version 2 (version 2 adds an \"answer\""},
        {[](json& j) { j["steps"][0].erase("answer"); },
         "demo.json: steps[0].answer is missing: step \"One\" of lesson demo asks a question and every question "
         "needs an answer"},
        {[](json& j) { j["steps"][0]["answer"] = " "; }, "demo.json: steps[0].answer must not be empty"},
        {[](json& j) { j["steps"][0]["answer"] = "{light.colour}"; },
         "demo.json: steps[0].answer uses the unknown placeholder {light.colour}"},
        {[](json& j) { j["format"] = "gbuffer-lab-session"; }, "demo.json: format must be \"gbuffer-lab-lesson\""},
        {[](json& j) { j["steps"][0]["pipeline"]["cull"] = "sideways"; },
         "demo.json: steps[0].pipeline.cull must be one of back, front, none, flip or stencil (got \"sideways\")"},
        {[](json& j) { j["setup"]["pipeline"]["mode"] = "magic"; }, "demo.json: setup.pipeline.mode must be one of"},
        {[](json& j) { j["steps"][0].erase("question"); }, "demo.json: steps[0].question is missing"},
        {[](json& j) { j["steps"][0]["look"] = "  "; }, "demo.json: steps[0].look must not be empty"},
        {[](json& j) { j.erase("title"); }, "demo.json: title is missing"},
        {[](json& j) { j["steps"][0]["equation"] = "{light.colour}"; },
         "demo.json: steps[0].equation uses the unknown placeholder {light.colour}"},
        {[](json& j) { j["steps"][0]["colour"] = 1; }, "demo.json: steps[0].colour is not a known field"},
        {[](json& j) { j["steps"][0]["claim"]["kind"] = "looks_nice"; },
         "demo.json: steps[0].claim.kind must be one of"},
        {[](json& j) { j["steps"][0]["claim"]["reference"]["cull"] = 3; },
         "demo.json: steps[0].claim.reference.cull must be one of"},
        {[](json& j) { j["steps"][0]["claim"]["light"] = 9; },
         "demo.json: steps[0].claim.light must be a whole number from 0 to 3"},
        {[](json& j) { j["steps"][0].erase("pixel"); },
         "demo.json: steps[0].claim.kind is a claim about the step's pixel"},
        {[](json& j) { j["steps"][0]["selected_light"] = 4; },
         "demo.json: steps[0].selected_light must be a whole number from -1 to 3"},
        {[](json& j) { j["steps"][0]["camera"]["fov_y_degrees"] = 0; },
         "demo.json: steps[0].camera.fov_y_degrees must be between 1 and 179"},
        {[](json& j) {
             j["steps"][0]["lights"] = json::array({{{"position", {0, 1, 0}}}});
         },
         "demo.json: steps[0].lights[0].color is missing"},
        {[](json& j) { j["steps"][0]["viewer"] = "stencil"; }, "demo.json: steps[0].viewer must be one of"},
        {[](json& j) { j["steps"] = json::array(); }, "demo.json: steps must be an array of at least one step"},
        {[](json& j) { j["id"] = "Has Space"; }, "demo.json: id must be lower-case letters"},
        {[](json& j) { j["steps"][0]["pipeline"]["volume_scale"] = 0.0; },
         "demo.json: steps[0].pipeline.volume_scale must be between"},
        {[](json& j) { j["setup"]["scene"]["glass"] = 1; }, "demo.json: setup.scene.glass must be true or false"},
        {[](json& j) { j["steps"][0]["scene"]["glass"] = "yes"; },
         "demo.json: steps[0].scene.glass must be true or false"},
        {[](json& j) { j["steps"][0]["scene"]["panes"] = 3; }, "demo.json: steps[0].scene.panes is not a known field"},
        {[](json& j) {
             j["steps"][0]["predict"] = {{"prompt", "p"},
                                         {"choices", {"a", "b"}},
                                         {"correct", 0},
                                         {"explain", "e"},
                                         {"before", {{"scene", {{"glass", true}}}}}};
         },
         "demo.json: steps[0].predict.before.scene.glass cannot differ from the step's"},
    };
    for (auto const& c : cases) {
        json j = minimalLesson();
        c.breakIt(j);
        std::string const e = lessonError(j);
        EXPECT_EQ(e.rfind(c.expect, 0), 0u) << "got: " << e << "\nwant: " << c.expect;
    }
}

// "scene": {"glass": true} (issue 47): in setup it holds for every step, a step may turn it off again,
// the step's scene is then "default+glass", and a lesson written back keeps it. No shipped lesson but
// transparency stands the panes, so no other frame changed.
TEST(LessonFile, AStepMayAskForTheGlassScene) {
    json j = minimalLesson();
    j["setup"]["scene"]["glass"] = true;
    j["steps"].push_back(j["steps"][0]);
    j["steps"][1]["scene"]["glass"] = false;
    LessonLoad const l = parseLesson(j.dump(), "demo.json");
    ASSERT_TRUE(l.lesson) << l.error;
    EXPECT_TRUE(l.lesson->steps[0].defaultSceneGlass);
    EXPECT_EQ(l.lesson->steps[0].defaultSceneLights, 4);
    EXPECT_FALSE(l.lesson->steps[1].defaultSceneGlass);
    EXPECT_EQ(lessonStepScene(*l.lesson, 0), "default+glass");
    EXPECT_EQ(lessonStepScene(*l.lesson, 1), "default");
    LessonLoad const again = parseLesson(lessonToJson(*l.lesson), "again.json");
    ASSERT_TRUE(again.lesson) << again.error;
    EXPECT_TRUE(again.lesson->steps[0].defaultSceneGlass);
    EXPECT_FALSE(again.lesson->steps[1].defaultSceneGlass);

    LessonLibrary const lib = loadLessonDir(defaultLessonDir());
    int glassSteps = 0;
    for (Lesson const& shipped : lib.lessons)
        for (LessonStep const& s : shipped.steps) {
            EXPECT_EQ(s.defaultSceneGlass, shipped.id == "transparency") << shipped.id;
            glassSteps += s.defaultSceneGlass;
        }
    EXPECT_EQ(glassSteps, 3);
}

// A claim's numbers are read through claimNumberFields(): a value past a field's range is refused
// with the table's range, and an optional field left out is the table's default (LessonClaim{}'s).
TEST(LessonFile, ClaimNumbersTakeTheirRangesAndDefaultsFromTheTable) {
    // A claim of a kind that takes each number, valid as it stands (the step of minimalLesson() has a pixel
    // and four lights).
    json const reference = {{"cull", "front"}};
    std::map<std::string, json> const claims{
        {"tolerance", {{"kind", "loses_light"}, {"light", 1}, {"reference", reference}}},
        {"bound", {{"kind", "same_image"}, {"reference", reference}, {"bound", 0.5}}},
        {"at_least", {{"kind", "position_error_below"}, {"bound", 1e6}}},
        {"min_fraction", {{"kind", "fewer_lit_pixels"}, {"reference", reference}, {"min_fraction", 0.5}}},
        {"max_fraction", {{"kind", "differs_from"}, {"reference", reference}, {"bound", 0.0}, {"min_fraction", 0.0}}},
    };
    ASSERT_EQ(claims.size(), claimNumberFields().size());
    for (ClaimNumberField const& f : claimNumberFields()) {
        std::string const name(f.name);
        ASSERT_TRUE(claims.count(name)) << name << " has no claim in this test";
        json j = minimalLesson();
        j["steps"][0]["claim"] = claims.at(name);
        LessonLoad const ok = parseLesson(j.dump(), "demo.json");
        ASSERT_TRUE(ok.lesson) << name << ": " << ok.error;
        ASSERT_TRUE(ok.lesson->steps[0].claim);
        LessonClaim const& claim = *ok.lesson->steps[0].claim;
        if (!j["steps"][0]["claim"].contains(name)) {
            EXPECT_EQ(claim.*f.member, f.defaultValue()) << name << " left out is not its default";
        }
        j["steps"][0]["claim"][name] = double(f.max) + 1.0;
        std::string const e = lessonError(j);
        std::string const want = "demo.json: steps[0].claim." + name + " must be a number from " + json(f.min).dump() +
                                 " to " + json(f.max).dump();
        EXPECT_EQ(e.rfind(want, 0), 0u) << e << "\nwanted: " << want;
    }
    // The defaults the shipped lessons rely on.
    EXPECT_EQ(findClaimNumberField("tolerance")->defaultValue(), 0.02f);
    EXPECT_EQ(findClaimNumberField("max_fraction")->defaultValue(), 1.0f);
    EXPECT_EQ(findClaimNumberField("at_least")->defaultValue(), 0.0f);
    EXPECT_FALSE(findClaimNumberField("light")) << "light's range is the step's light count, not the table's";
}

// An old lesson's "blit" (the depth copy's old name) reads as depth_copy wherever a lesson names
// settings: the step's pipeline over a setup that says depth_copy, a claim's reference, A/B's side B.
TEST(LessonFile, TheDepthCopysOldNameStillLoads) {
    json j = minimalLesson();
    j["setup"]["pipeline"]["depth_copy"] = "shader";
    j["steps"][0]["pipeline"]["blit"] = "off";
    j["steps"][0]["claim"] = {{"kind", "same_image"}, {"reference", {{"blit", "blit"}}}, {"bound", 0.5}};
    j["steps"][0]["ab"] = {{"view", "split"}, {"b", {{"blit", "shader"}}}};
    LessonLoad const l = parseLesson(j.dump(), "demo.json");
    ASSERT_TRUE(l.lesson) << l.error;
    LessonStep const& step = l.lesson->steps[0];
    EXPECT_EQ(step.state.pipeline.depthCopy, DepthCopy::Off);  // the step's old key over the setup's new one
    ASSERT_TRUE(step.claim && step.claim->reference);
    EXPECT_EQ(step.claim->reference->depthCopy, DepthCopy::Blit);
    ASSERT_TRUE(step.state.ab);
    EXPECT_EQ(step.state.ab->b.depthCopy, DepthCopy::Shader);
}

TEST(LessonFile, StepReferences) {
    LessonLibrary lib;
    lib.lessons.push_back(*parseLesson(minimalLesson().dump(), "demo.json").lesson);
    EXPECT_EQ(findLessonStep(lib, "demo").step, 0);
    EXPECT_EQ(findLessonStep(lib, "demo:1").lesson, 0);
    EXPECT_NE(findLessonStep(lib, "demo:2").error.find("has steps 1 to 1"), std::string::npos);
    EXPECT_NE(findLessonStep(lib, "demo:x").error.find("not \"x\""), std::string::npos);
    EXPECT_NE(findLessonStep(lib, "other").error.find("(lessons: demo)"), std::string::npos);
}

TEST(LessonFile, ASavedStepReadsBackAsTheSameState) {
    std::string const dir = test::freshTempDir("lesson_save");
    std::string const path = dir + "/My Lesson.json";
    LessonStep step = parseLesson(minimalLesson().dump(), "demo.json").lesson->steps[0];
    step.claim.reset();  // saved steps carry no claim: a teacher writes that by hand
    step.state.lights[1].kq = 0.123f;
    step.state.pipeline.shininess = 12.5f;
    ASSERT_FALSE(appendLessonStep(path, step));
    ASSERT_FALSE(appendLessonStep(path, step));  // appends to the file now present
    LessonLoad const back = loadLesson(path);
    ASSERT_TRUE(back.lesson) << back.error;
    EXPECT_EQ(back.lesson->id, "my_lesson");
    ASSERT_EQ(back.lesson->steps.size(), 2u);
    LessonStep const& s = back.lesson->steps[1];
    EXPECT_EQ(s.state.lights, step.state.lights);
    EXPECT_EQ(s.state.pipeline, step.state.pipeline);
    EXPECT_EQ(s.state.camera.position, step.state.camera.position);
    EXPECT_EQ(s.state.camera.yawDegrees, step.state.camera.yawDegrees);
    EXPECT_EQ(s.state.selectedLight, 2);
    EXPECT_EQ(s.state.activeViewer, int(ViewerKind::Depth));
    EXPECT_EQ(s.text.equation, "r = {light.radius}");
    // A file that is not a lesson is not overwritten.
    std::ofstream(dir + "/notes.json") << "{}";
    auto const err = appendLessonStep(dir + "/notes.json", step);
    ASSERT_TRUE(err);
    EXPECT_NE(err->find("notes.json: format is missing"), std::string::npos) << *err;
}

// --- lessons on a glTF scene ------------------------------------------------------------------

// A lesson on the test data's triangle: its own lights and camera, as a glTF lesson must have.
json onScene(std::string const& scene) {
    json j = minimalLesson();
    j["scene"] = scene;
    j["setup"]["lights"] = json::parse(R"([{"position": [0, 1, 2], "color": [1, 1, 1], "intensity": 1,
                                             "kc": 1, "kl": 0.35, "kq": 0.44, "threshold": 0.01953125}])");
    j["setup"]["camera"] = json::parse(R"({"position": [0, 0, 3], "look_at": [0, 0, 0]})");
    j["steps"][0].erase("claim");  // its light 1 is the default scene's
    j["steps"][0]["selected_light"] = 0;
    return j;
}

// Copies the test data's triangle (its .gltf and .bin) into `dir`.
void copyTriangle(std::string const& dir) {
    namespace fs = std::filesystem;
    for (char const* f : {"triangle.gltf", "triangle.bin"})
        fs::copy_file(fs::path(test::dataDir()) / "gltf" / f, fs::path(dir) / f, fs::copy_options::overwrite_existing);
}

// Sets an environment variable for one scope and puts the old value back.
struct ScopedEnv {
    std::string name;
    std::optional<std::string> old;
    ScopedEnv(std::string n, std::string const& value) : name(std::move(n)) {
        if (char const* v = std::getenv(name.c_str())) old = v;
        ::setenv(name.c_str(), value.c_str(), 1);
    }
    ~ScopedEnv() {
        if (old)
            ::setenv(name.c_str(), old->c_str(), 1);
        else
            ::unsetenv(name.c_str());
    }
};

TEST(LessonScene, ASceneIsFoundBesideTheLessonThenInTheSharedModels) {
    namespace fs = std::filesystem;
    std::string const dir = test::freshTempDir("lesson_scene");
    copyTriangle(dir);
    std::ofstream(dir + "/tri.json") << onScene("triangle.gltf").dump();
    LessonLoad const beside = loadLesson(dir + "/tri.json");
    ASSERT_TRUE(beside.lesson) << beside.error;
    EXPECT_EQ(beside.lesson->scene, "triangle.gltf");
    EXPECT_TRUE(fs::equivalent(beside.lesson->scenePath, dir + "/triangle.gltf")) << beside.lesson->scenePath;
    EXPECT_EQ(beside.lesson->steps[0].state.lights.size(), 1u);  // the setup's, not the default scene's 32

    // Not beside the lesson: the shared models folder ($GBL_SHARED_GLTF_DIR here) is next.
    std::string const models = test::freshTempDir("lesson_scene_models");
    fs::create_directories(models + "/Tri");
    copyTriangle(models + "/Tri");
    std::string const lessons = test::freshTempDir("lesson_scene_lessons");
    std::ofstream(lessons + "/tri.json") << onScene("Tri/triangle.gltf").dump();
    {
        ScopedEnv env("GBL_SHARED_GLTF_DIR", models);
        EXPECT_EQ(sharedModelsDir(), models);
        LessonLoad const shared = loadLesson(lessons + "/tri.json");
        ASSERT_TRUE(shared.lesson) << shared.error;
        EXPECT_TRUE(fs::equivalent(shared.lesson->scenePath, models + "/Tri/triangle.gltf"));
    }
    // Without it, the lesson is refused in one sentence naming the field and both places looked in,
    // and the other lessons of the folder still load.
    {
        ScopedEnv env("GBL_SHARED_GLTF_DIR", dir + "/no_models");
        std::ofstream(lessons + "/a.json") << minimalLesson().dump();
        LessonLibrary const lib = loadLessonDir(lessons);
        ASSERT_EQ(lib.lessons.size(), 1u);
        EXPECT_EQ(lib.lessons[0].id, "demo");
        ASSERT_EQ(lib.errors.size(), 1u);
        std::string const want = lessons + "/tri.json: scene \"Tri/triangle.gltf\" is not a file: neither " + lessons +
                                 "/Tri/triangle.gltf nor " + dir + "/no_models/Tri/triangle.gltf exists";
        EXPECT_NE(lib.errors[0].find(want), std::string::npos) << lib.errors[0];
    }
}

TEST(LessonScene, TheSharedModelsFolderIsTheDefault) {
    std::string const box = test::sharedGltfDir() + "/Box/Box.gltf";
    if (!std::filesystem::exists(box)) GTEST_SKIP() << "needs the shared models: " << box << " is absent";
    if (std::getenv("GBL_SHARED_GLTF_DIR")) GTEST_SKIP() << "GBL_SHARED_GLTF_DIR is set: the default is not used";
    LessonLoad const l = parseLesson(onScene("Box/Box.gltf").dump(), test::freshTempDir("lesson_box") + "/box.json");
    ASSERT_TRUE(l.lesson) << l.error;
    EXPECT_TRUE(std::filesystem::equivalent(l.lesson->scenePath, box)) << l.lesson->scenePath;
}

TEST(LessonScene, BadScenesNameTheField) {
    std::string const dir = test::freshTempDir("lesson_scene_bad");
    copyTriangle(dir);
    std::string const label = dir + "/x.json";
    auto error = [&](json const& j) {
        LessonLoad const l = parseLesson(j.dump(), label);
        EXPECT_FALSE(l.lesson) << "parsed although broken";
        return l.error;
    };
    EXPECT_EQ(error(onScene("")), label + ": scene must be the path of a glTF file (.gltf or .glb)");
    json number = onScene("x");
    number["scene"] = 3;
    EXPECT_EQ(error(number), label + ": scene must be the path of a glTF file (.gltf or .glb)");
    EXPECT_EQ(error(onScene("triangle.bin")), label + ": scene must name a .gltf or .glb file (got \"triangle.bin\")");
    // The default scene's lights and camera do not fit another scene: a glTF lesson names its own.
    json noLights = onScene("triangle.gltf");
    noLights["setup"].erase("lights");
    EXPECT_NE(error(noLights).find(label + ": steps[0].lights is missing: a lesson on a glTF scene"),
              std::string::npos);
    json noCamera = onScene("triangle.gltf");
    noCamera["setup"].erase("camera");
    noCamera["steps"][0].erase("camera");
    EXPECT_NE(error(noCamera).find(label + ": steps[0].camera.position is missing: a lesson on a glTF scene"),
              std::string::npos);
}

TEST(LessonScene, ASavedStepKeepsItsScene) {
    namespace fs = std::filesystem;
    std::string const dir = test::freshTempDir("lesson_scene_save");
    copyTriangle(dir);
    std::string const scene = dir + "/triangle.gltf";
    LessonStep const step = parseLesson(minimalLesson().dump(), "demo.json").lesson->steps[0];
    std::string const path = dir + "/saved.json";
    ASSERT_FALSE(appendLessonStep(path, step, scene));
    ASSERT_FALSE(appendLessonStep(path, step, scene));
    LessonLoad const back = loadLesson(path);
    ASSERT_TRUE(back.lesson) << back.error;
    EXPECT_EQ(back.lesson->steps.size(), 2u);
    EXPECT_TRUE(fs::equivalent(back.lesson->scenePath, scene));
    // A step set up on another scene is not added to it, and the file stays as it was.
    auto const other = appendLessonStep(path, step);
    ASSERT_TRUE(other);
    EXPECT_NE(other->find("and the editor shows the default scene"), std::string::npos) << *other;
    EXPECT_EQ(loadLesson(path).lesson->steps.size(), 2u);
}

TEST(LessonFile, ABrokenFileInTheFolderIsReportedAndTheOthersLoad) {
    std::string const dir = test::freshTempDir("lesson_dir");
    std::ofstream(dir + "/a.json") << minimalLesson().dump();
    json bad = minimalLesson();
    bad["steps"][0]["pipeline"]["blit"] = "copy";
    std::ofstream(dir + "/b.json") << bad.dump();
    std::ofstream(dir + "/c.json") << minimalLesson().dump();  // the same id again
    json noAnswer = minimalLesson();
    noAnswer["id"] = "other";
    noAnswer["steps"][0].erase("answer");
    std::ofstream(dir + "/d.json") << noAnswer.dump();
    LessonLibrary const lib = loadLessonDir(dir);
    ASSERT_EQ(lib.lessons.size(), 1u);
    ASSERT_EQ(lib.errors.size(), 3u);
    EXPECT_NE(lib.errors[2].find("d.json: steps[0].answer is missing: step \"One\" of lesson other"), std::string::npos)
        << lib.errors[2];
    EXPECT_NE(lib.errors[0].find("b.json: steps[0].pipeline.blit must be one of blit, shader or off"),
              std::string::npos)
        << lib.errors[0];
    EXPECT_NE(lib.errors[1].find("c.json: id \"demo\" is already used"), std::string::npos) << lib.errors[1];
}

}  // namespace

TEST(LessonFile, ABadAbFieldIsNamed) {
    json j = minimalLesson();
    j["steps"][0]["ab"] = {{"b", {{"zebra", 1}}}};
    EXPECT_NE(lessonError(j).find("steps[0].ab.b.zebra"), std::string::npos) << lessonError(j);
    j["steps"][0]["ab"] = {{"b", {{"cull", "sideways"}}}};
    EXPECT_NE(lessonError(j).find("steps[0].ab.b.cull"), std::string::npos) << lessonError(j);
    j["steps"][0]["ab"] = {{"view", "both"}, {"b", {{"cull", "front"}}}};
    EXPECT_NE(lessonError(j).find("steps[0].ab.view"), std::string::npos) << lessonError(j);
    j["steps"][0]["ab"] = {{"b", json::object()}};
    EXPECT_NE(lessonError(j).find("steps[0].ab.b"), std::string::npos) << lessonError(j);
}
