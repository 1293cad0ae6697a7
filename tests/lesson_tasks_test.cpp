// Lesson tasks on the CPU (issue 27): each kind's goal is false when the step shows, true after the
// intended action and false after a wrong one; broken tasks give one message naming the field; the
// hint's timing; tasks from an author's change; the shipped tasks can be met from their step's state.
// The kind tables against the shipped files and docs/lessons.md: lesson_kinds_test.
#include "model/lesson_tasks.h"
#include "core/light_math.h"
#include "core/pipeline_fields.h"
#include "model/lesson_claims.h"
#include "model/lesson_state.h"
#include "model/lesson_text.h"
#include "run_command.h"
#include "session/lesson_file.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <functional>

using namespace gbl;
using namespace gbl::ui;
using nlohmann::json;

namespace {

// One light of radius 10.29 (Kc 1, Kl 0.35, Kq 0.44, Imax 1), the camera-inside cull, a pixel.
json lesson() {
    return json::parse(R"({
      "format": "gbuffer-lab-lesson", "version": 2, "id": "t", "title": "T", "size": [480, 270],
      "steps": [
        {"title": "Radius", "look": "l", "equation": "e", "question": "q?", "answer": "a.",
         "lights": [{"position": [0, 1, 3], "color": [1, 1, 1], "intensity": 1, "kc": 1, "kl": 0.35, "kq": 0.44,
                     "threshold": 0.01953125}],
         "selected_light": 0,
         "tasks": [{"kind": "light_field", "goal": "Make the radius 5 by changing only Kq", "hint": "Lights: drag Kq",
                    "light": 0, "field": "radius", "value": 5, "tolerance": 0.2, "only_changed": ["kq"]}]},
        {"title": "Cull", "look": "l", "equation": "e", "question": "q?", "answer": "a.",
         "pipeline": {"mode": "volumes", "cull": "front"},
         "tasks": [{"kind": "setting", "goal": "Find the cull mode that loses the light", "hint": "Pipeline: cull",
                    "setting": "cull", "value": "back"},
                   {"kind": "setting", "goal": "Turn the blit off", "hint": "Pipeline: blit",
                    "setting": "blit", "value": "off"}]},
        {"title": "Pixel", "look": "l", "equation": "e", "question": "q?", "answer": "a.",
         "pixel": [0.5, 0.82],
         "tasks": [{"kind": "pixel", "goal": "Lock a pixel of the far wall", "hint": "Click it in the viewport",
                    "region": [100, 40, 379, 90]}]}]
    })");
}

Lesson load(json const& j) {
    LessonLoad l = parseLesson(j.dump(), "t.json");
    EXPECT_TRUE(l.lesson) << l.error;
    return l.lesson ? *l.lesson : Lesson{};
}

// The editor as the step shows it: the step's lights and pipeline, its pixel locked.
struct StepView {
    std::vector<PointLight> lights;
    PipelineSettings pipeline;
    bool locked = false;
    std::optional<glm::ivec2> pixel;
    glm::ivec2 frame{480, 270};

    explicit StepView(LessonStep const& s, glm::ivec2 frameSize = {480, 270})
        : lights(s.state.lights), pipeline(s.state.pipeline), locked(s.state.pixel.has_value()), frame(frameSize) {
        if (s.state.pixel) pixel = lessonPixel(*s.state.pixel, frame);
    }
    TaskContext context(LessonStep const& s, Lesson const& l) const {
        TaskContext c;
        c.lights = lights;
        c.stepLights = s.state.lights;
        c.pipeline = &pipeline;
        c.pixelLocked = locked;
        c.pixel = pixel;
        c.frameSize = frame;
        c.lessonSize = {l.width, l.height};
        return c;
    }
};

// Kq that gives `light` the radius r: Kc + Kl·r + Kq·r² = Imax / threshold.
float kqForRadius(PointLight const& light, float r) {
    float const imax = std::max({light.color.r, light.color.g, light.color.b}) * light.intensity;
    return (imax / light.threshold - light.kc - light.kl * r) / (r * r);
}

TEST(LessonTasks, LightFieldFalseAtStartTrueByKqFalseByKl) {
    Lesson const l = load(lesson());
    LessonStep const& s = l.steps[0];
    ASSERT_EQ(s.tasks.size(), 1u);
    StepView e(s);
    EXPECT_NEAR(lightRadius(e.lights[0]).radius, 10.29f, 0.01f);
    EXPECT_FALSE(taskMet(s.tasks[0], e.context(s, l)));  // the step as shown

    e.lights[0].kq = kqForRadius(e.lights[0], 5.0f);  // the intended action: Kq alone
    EXPECT_NEAR(lightRadius(e.lights[0]).radius, 5.0f, 0.01f);
    EXPECT_TRUE(taskMet(s.tasks[0], e.context(s, l)));
    e.lights[0].kq = kqForRadius(e.lights[0], 5.25f);  // just outside 5 ± 0.2
    EXPECT_FALSE(taskMet(s.tasks[0], e.context(s, l)));

    // The wrong action: the same radius reached through Kl.
    StepView wrong(s);
    wrong.lights[0].kl = (1.0f / wrong.lights[0].threshold - 1.0f - 0.44f * 25.0f) / 5.0f;
    EXPECT_NEAR(lightRadius(wrong.lights[0]).radius, 5.0f, 0.01f);
    EXPECT_FALSE(taskMet(s.tasks[0], wrong.context(s, l)));
    // Kq right, but the intensity touched as well.
    StepView both(s);
    both.lights[0].kq = kqForRadius(both.lights[0], 5.0f);
    both.lights[0].position.x += 1.0f;
    EXPECT_FALSE(taskMet(s.tasks[0], both.context(s, l)));
    // The light deleted: not met, no crash.
    StepView none(s);
    none.lights.clear();
    EXPECT_FALSE(taskMet(s.tasks[0], none.context(s, l)));
}

TEST(LessonTasks, SettingFalseAtStartTrueByTheRightValueFalseByAnother) {
    Lesson const l = load(lesson());
    LessonStep const& s = l.steps[1];
    ASSERT_EQ(s.tasks.size(), 2u);
    StepView e(s);
    EXPECT_FALSE(taskMet(s.tasks[0], e.context(s, l)));
    EXPECT_FALSE(taskMet(s.tasks[1], e.context(s, l)));
    e.pipeline.cull = CullMode::None;  // wrong: none still shows the light from inside
    EXPECT_FALSE(taskMet(s.tasks[0], e.context(s, l)));
    e.pipeline.cull = CullMode::Back;
    EXPECT_TRUE(taskMet(s.tasks[0], e.context(s, l)));
    e.pipeline.depthCopy = DepthCopy::Shader;  // wrong: a shader copy is still a copy
    EXPECT_FALSE(taskMet(s.tasks[1], e.context(s, l)));
    e.pipeline.depthCopy = DepthCopy::Off;
    EXPECT_TRUE(taskMet(s.tasks[1], e.context(s, l)));
}

TEST(LessonTasks, PixelFalseAtStartTrueInsideTheRegionAtAnyFrameSize) {
    Lesson const l = load(lesson());
    LessonStep const& s = l.steps[2];
    StepView e(s);
    EXPECT_EQ(e.pixel, glm::ivec2(240, 221));
    EXPECT_FALSE(taskMet(s.tasks[0], e.context(s, l)));
    e.pixel = glm::ivec2(200, 60);  // inside, but the inspector follows the mouse
    e.locked = false;
    EXPECT_FALSE(taskMet(s.tasks[0], e.context(s, l)));
    e.locked = true;
    EXPECT_TRUE(taskMet(s.tasks[0], e.context(s, l)));
    e.pixel = glm::ivec2(200, 91);  // one row below the region: a wrong pixel
    EXPECT_FALSE(taskMet(s.tasks[0], e.context(s, l)));
    e.pixel = glm::ivec2(379, 90);  // the corner is inside (inclusive)
    EXPECT_TRUE(taskMet(s.tasks[0], e.context(s, l)));
    // A viewport twice the lesson's size: the region scales with it.
    StepView big(s, {960, 540});
    big.pixel = glm::ivec2(400, 120);
    EXPECT_TRUE(taskMet(s.tasks[0], big.context(s, l)));
    big.pixel = glm::ivec2(400, 182);  // row 91 at the lesson's size
    EXPECT_FALSE(taskMet(s.tasks[0], big.context(s, l)));
}

TEST(LessonTasks, HintShowsAfterAboutFortyFiveSecondsUnmet) {
    Lesson const l = load(lesson());
    LessonStep const& s = l.steps[1];
    StepView e(s);
    std::vector<TaskProgress> p = startTasks(s.tasks.size(), 100.0);
    updateTasks(p, s.tasks, e.context(s, l), 100.0 + kTaskHintSeconds - 1.0);
    EXPECT_FALSE(p[0].hint);
    EXPECT_FALSE(p[0].met);
    updateTasks(p, s.tasks, e.context(s, l), 100.0 + kTaskHintSeconds);
    EXPECT_TRUE(p[0].hint);
    EXPECT_TRUE(p[1].hint);
    e.pipeline.cull = CullMode::Back;  // met: ticked, no hint
    updateTasks(p, s.tasks, e.context(s, l), 150.0);
    EXPECT_TRUE(p[0].met);
    EXPECT_FALSE(p[0].hint);
    EXPECT_TRUE(p[1].hint);             // the other task is still unmet
    e.pipeline.cull = CullMode::Front;  // undone at 160: the hint waits a whole period again
    updateTasks(p, s.tasks, e.context(s, l), 160.0);
    EXPECT_FALSE(p[0].met);
    EXPECT_FALSE(p[0].hint);
    updateTasks(p, s.tasks, e.context(s, l), 160.0 + kTaskHintSeconds - 1.0);
    EXPECT_FALSE(p[0].hint);
    updateTasks(p, s.tasks, e.context(s, l), 160.0 + kTaskHintSeconds);
    EXPECT_TRUE(p[0].hint);
    EXPECT_GE(kTaskHintSeconds, 30.0);  // "about 45 s": long enough to try first
    EXPECT_LE(kTaskHintSeconds, 60.0);
}

TEST(LessonTasks, BrokenTasksNameTheField) {
    struct Case {
        std::function<void(json&)> breakIt;
        std::string expect;
    };
    auto task = [](json& j, int step, int i) -> json& { return j["steps"][step]["tasks"][i]; };
    std::vector<Case> const cases{
        {[&](json& j) { j["steps"][0]["tasks"] = json::array(); }, "t.json: steps[0].tasks must be an array"},
        {[&](json& j) { task(j, 0, 0)["kind"] = "radius"; },
         "t.json: steps[0].tasks[0].kind must be one of light_field, setting, pixel (got \"radius\")"},
        {[&](json& j) { task(j, 0, 0).erase("kind"); }, "t.json: steps[0].tasks[0].kind is missing"},
        {[&](json& j) { task(j, 0, 0).erase("hint"); }, "t.json: steps[0].tasks[0].hint is missing"},
        {[&](json& j) { task(j, 0, 0)["goal"] = ""; }, "t.json: steps[0].tasks[0].goal must not be empty"},
        {[&](json& j) { task(j, 0, 0)["goal"] = "{nope}"; },
         "t.json: steps[0].tasks[0].goal uses the unknown placeholder {nope}"},
        {[&](json& j) { task(j, 0, 0)["value"] = "five"; }, "t.json: steps[0].tasks[0].value must be a number from"},
        {[&](json& j) { task(j, 0, 0).erase("tolerance"); },
         "t.json: steps[0].tasks[0].tolerance is missing (a light_field task needs it)"},
        {[&](json& j) { task(j, 0, 0)["light"] = 1; },
         "t.json: steps[0].tasks[0].light must be a whole number from 0 to 0"},
        {[&](json& j) { task(j, 0, 0)["field"] = "Kq"; },
         "t.json: steps[0].tasks[0].field must be one of x, y, z, r, g, b, kc, kl, kq, intensity"},
        {[&](json& j) {
             task(j, 0, 0)["only_changed"] = {"kq", "radius"};
         },
         "t.json: steps[0].tasks[0].only_changed[1] must be a field of kLightFields"},
        {[&](json& j) {
             task(j, 0, 0)["region"] = {0, 0, 1, 1};
         },
         "t.json: steps[0].tasks[0].region is not a field of a light_field task"},
        {[&](json& j) { task(j, 0, 0)["value"] = 10.29; },
         "t.json: steps[0].tasks[0] is already met in the step's own state"},
        {[&](json& j) { task(j, 1, 1)["value"] = "none"; },
         "t.json: steps[1].tasks[1].value \"none\" is not a value of depth_copy"},
        {[&](json& j) { task(j, 1, 0)["setting"] = "culling"; },
         "t.json: steps[1].tasks[0].setting must be a pipeline setting: one of mode, cull, depth_copy"},
        {[&](json& j) { task(j, 1, 0)["tolerance"] = 0.1; },
         "t.json: steps[1].tasks[0].tolerance is only for a number setting"},
        {[&](json& j) { task(j, 1, 0)["value"] = "front"; }, "t.json: steps[1].tasks[0] is already met"},
        {[&](json& j) {
             task(j, 2, 0)["region"] = {0, 0, 480, 10};
         },
         "t.json: steps[2].tasks[0].region[2] must be a whole number from 0 to 479"},
        {[&](json& j) {
             task(j, 2, 0)["region"] = {10, 0, 5, 10};
         },
         "t.json: steps[2].tasks[0].region must have x0 <= x1 and y0 <= y1"},
        {[&](json& j) {
             task(j, 2, 0)["region"] = {200, 200, 300, 250};
         },
         "t.json: steps[2].tasks[0] is already met"},  // the step's own pixel (240, 221) is inside
        {[&](json& j) { task(j, 2, 0).erase("region"); },
         "t.json: steps[2].tasks[0].region is missing (a pixel task needs it)"},
    };
    for (auto const& c : cases) {
        json j = lesson();
        c.breakIt(j);
        LessonLoad const l = parseLesson(j.dump(), "t.json");
        EXPECT_FALSE(l.lesson);
        EXPECT_EQ(l.error.rfind(c.expect, 0), 0u) << "got: " << l.error << "\nwant: " << c.expect;
    }
}

TEST(LessonTasks, ABrokenTaskIsOneErrorAndTheOtherLessonsLoad) {
    std::string const dir = test::freshTempDir("lesson_tasks_dir");
    std::ofstream(dir + "/a.json") << lesson().dump();
    json bad = lesson();
    bad["id"] = "bad";
    bad["steps"][1]["tasks"][0]["value"] = "sideways";
    std::ofstream(dir + "/b.json") << bad.dump();
    LessonLibrary const lib = loadLessonDir(dir);
    ASSERT_EQ(lib.lessons.size(), 1u);
    EXPECT_EQ(lib.lessons[0].id, "t");
    ASSERT_EQ(lib.errors.size(), 1u);
    EXPECT_NE(lib.errors[0].find("b.json: steps[1].tasks[0].value \"sideways\" is not a value of cull"),
              std::string::npos)
        << lib.errors[0];
}

TEST(LessonTasks, ASavedLessonKeepsItsTasks) {
    std::string const path = test::freshTempDir("lesson_tasks_save") + "/saved.json";
    Lesson const l = load(lesson());
    ASSERT_FALSE(appendLessonStep(path, l.steps[0]));
    ASSERT_FALSE(appendLessonStep(path, l.steps[1]));
    LessonLoad const back = loadLesson(path);
    ASSERT_TRUE(back.lesson) << back.error;
    ASSERT_EQ(back.lesson->steps[0].tasks.size(), 1u);
    EXPECT_EQ(back.lesson->steps[0].tasks[0].onlyChanged, std::vector<std::string>{"kq"});
    ASSERT_EQ(back.lesson->steps[1].tasks.size(), 2u);
    // Written as "blit" (the old name), read back under the field's name.
    EXPECT_EQ(back.lesson->steps[1].tasks[1].setting, "depth_copy");
}

// --- tasks from an author's change ("Save this state as a step" with "Add tasks") ---------------

// What the editor would check a task against: `lights` and `pipeline` now, the step's lights.
TaskContext contextOf(std::vector<PointLight> const& lights, PipelineSettings const& pipeline,
                      std::vector<PointLight> const& stepLights) {
    TaskContext c;
    c.lights = lights;
    c.stepLights = stepLights;
    c.pipeline = &pipeline;
    c.frameSize = c.lessonSize = {480, 270};
    return c;
}

TEST(LessonTasks, AChangeBecomesOneTaskPerChangedSettingAndLightField) {
    Lesson const l = load(lesson());
    LessonStep const& start = l.steps[0];
    std::vector<PointLight> lights = start.state.lights;
    PipelineSettings pipeline = start.state.pipeline;
    EXPECT_TRUE(tasksFromChange(pipeline, pipeline, lights, lights).empty());  // nothing changed, nothing asked

    lights[0].kq = kqForRadius(lights[0], 5.0f);
    pipeline.cull = pipeline.cull == CullMode::Back ? CullMode::Front : CullMode::Back;
    pipeline.volumeScale = pipeline.volumeScale + 0.2f;
    std::vector<LessonTask> const tasks = tasksFromChange(start.state.pipeline, pipeline, start.state.lights, lights);
    ASSERT_EQ(tasks.size(), 3u);
    // Settings first, in pipelineFields() order, then the lights' fields.
    EXPECT_EQ(tasks[0].kind, TaskKind::Setting);
    EXPECT_EQ(tasks[0].setting, "cull");
    EXPECT_EQ(tasks[0].value, double(int(pipeline.cull)));
    EXPECT_EQ(tasks[0].tolerance, 0.0);  // a choice is exact
    EXPECT_NE(tasks[0].goal.find(pipeline.cull == CullMode::Back ? "to back" : "to front"), std::string::npos)
        << tasks[0].goal;
    EXPECT_EQ(tasks[1].setting, "volume_scale");
    EXPECT_NEAR(tasks[1].value, pipeline.volumeScale, 1e-6);
    PipelineField const* scale = findPipelineField("volume_scale");
    EXPECT_NEAR(tasks[1].tolerance, 0.01 * double(scale->max - scale->min), 1e-6);
    EXPECT_EQ(tasks[2].kind, TaskKind::LightField);
    EXPECT_EQ(tasks[2].light, 0);
    EXPECT_EQ(tasks[2].field, "kq");
    EXPECT_NEAR(tasks[2].value, lights[0].kq, 1e-7);
    EXPECT_EQ(tasks[2].onlyChanged, std::vector<std::string>{"kq"});
    for (LessonTask const& t : tasks) {
        EXPECT_FALSE(t.goal.empty());
        EXPECT_FALSE(t.hint.empty());
        EXPECT_FALSE(unknownPlaceholder(t.goal)) << t.goal;
        EXPECT_FALSE(unknownPlaceholder(t.hint)) << t.hint;
        // Unmet where the step starts, met once the change is made.
        EXPECT_FALSE(taskMet(t, contextOf(start.state.lights, start.state.pipeline, start.state.lights))) << t.goal;
        EXPECT_TRUE(taskMet(t, contextOf(lights, pipeline, start.state.lights))) << t.goal;
    }
    // The right Kq reached by also changing Kl does not count: only the changed fields may differ.
    std::vector<PointLight> wrong = lights;
    wrong[0].kl += 0.1f;
    EXPECT_FALSE(taskMet(tasks[2], contextOf(wrong, pipeline, start.state.lights)));
}

TEST(LessonTasks, AToleranceStaysBelowHalfTheChange) {
    PipelineSettings from;
    PipelineSettings to = from;
    to.volumeScale = from.volumeScale + 0.004f;  // smaller than 1 % of the range
    std::vector<LessonTask> const tasks = tasksFromChange(from, to, {}, {});
    ASSERT_EQ(tasks.size(), 1u);
    EXPECT_LT(tasks[0].tolerance, 0.002);
    std::vector<PointLight> const none;
    EXPECT_FALSE(taskMet(tasks[0], contextOf(none, from, none)));
    EXPECT_TRUE(taskMet(tasks[0], contextOf(none, to, none)));
}

TEST(LessonTasks, AStepSavedWithTasksFromAChangeReadsBackAndValidates) {
    Lesson const l = load(lesson());
    LessonStep step = l.steps[1];  // cull front, volumes; its own tasks dropped: the change makes new ones
    step.tasks.clear();
    step.tasksJson.clear();
    PipelineSettings to = step.state.pipeline;
    to.cull = CullMode::Flip;
    to.lightCubes = !to.lightCubes;
    std::vector<PointLight> lights = step.state.lights;
    lights[3].intensity = 2.5f;
    lights[3].position.x += 1.0f;
    step.tasks = tasksFromChange(step.state.pipeline, to, step.state.lights, lights);
    ASSERT_EQ(step.tasks.size(), 4u);  // cull, light_cubes, light 3's x and intensity

    std::string const path = test::freshTempDir("lesson_tasks_change") + "/authored.json";
    ASSERT_FALSE(appendLessonStep(path, step));
    LessonLoad const back = loadLesson(path);
    ASSERT_TRUE(back.lesson) << back.error;
    LessonStep const& s = back.lesson->steps[0];
    ASSERT_EQ(s.tasks.size(), step.tasks.size());
    for (std::size_t i = 0; i < s.tasks.size(); ++i) {
        LessonTask const& a = step.tasks[i];
        LessonTask const& b = s.tasks[i];
        EXPECT_EQ(b.kind, a.kind);
        EXPECT_EQ(b.goal, a.goal);
        EXPECT_EQ(b.hint, a.hint);
        EXPECT_EQ(b.setting, a.setting);
        EXPECT_EQ(b.light, a.light);
        EXPECT_EQ(b.field, a.field);
        EXPECT_EQ(b.onlyChanged, a.onlyChanged);
        EXPECT_NEAR(b.value, a.value, 1e-5 * std::max(1.0, std::abs(a.value))) << a.goal;
        EXPECT_NEAR(b.tolerance, a.tolerance, 1e-6) << a.goal;
        EXPECT_FALSE(taskMet(b, contextOf(s.state.lights, s.state.pipeline, s.state.lights))) << b.goal;
        EXPECT_TRUE(taskMet(b, contextOf(lights, to, s.state.lights))) << b.goal;
    }
    EXPECT_EQ(s.tasks[1].setting, "light_cubes");
    EXPECT_EQ(s.tasks[2].onlyChanged, (std::vector<std::string>{"x", "intensity"}));
    // The file writes a setting's value as a session does.
    std::ifstream in(path);
    json const file = json::parse(in);
    EXPECT_EQ(file["steps"][0]["tasks"][0]["value"], "flip");
    EXPECT_EQ(file["steps"][0]["tasks"][1]["value"], to.lightCubes);

    // A task already met where the step starts is refused before anything is written.
    LessonStep met = step;
    met.tasks = tasksFromChange(step.state.pipeline, to, step.state.lights, lights);
    met.tasks[0].value = double(int(step.state.pipeline.cull));
    auto const refused = appendLessonStep(path, met);
    ASSERT_TRUE(refused);
    EXPECT_NE(refused->find("step not saved: " + path + ": steps[1].tasks[0] is already met"), std::string::npos)
        << *refused;
    EXPECT_EQ(loadLesson(path).lesson->steps.size(), 1u);
}

// --- the shipped lessons ---------------------------------------------------------------------

LessonStep const* shipped(LessonLibrary const& lib, std::string const& ref, Lesson const** lesson) {
    LessonRef const r = findLessonStep(lib, ref);
    EXPECT_GE(r.lesson, 0) << r.error;
    if (r.lesson < 0) return nullptr;
    *lesson = &lib.lessons[std::size_t(r.lesson)];
    return &(*lesson)->steps[std::size_t(r.step)];
}

TEST(LessonTasks, ShippedTasksAreMetByTheIntendedActionOnly) {
    LessonLibrary const lib = loadLessonDir(defaultLessonDir());
    ASSERT_TRUE(lib.errors.empty()) << lib.errors.front();
    int withTasks = 0;
    for (Lesson const& l : lib.lessons)
        for (LessonStep const& s : l.steps) {
            withTasks += !s.tasks.empty();
            StepView const e(s, {l.width, l.height});
            for (LessonTask const& t : s.tasks) EXPECT_FALSE(taskMet(t, e.context(s, l))) << l.id << ": " << t.goal;
        }
    EXPECT_GE(withTasks, 4);

    Lesson const* l = nullptr;
    // attenuation:1: radius 5 ± 0.2 by Kq alone, not by Kl.
    LessonStep const* s = shipped(lib, "attenuation:1", &l);
    ASSERT_TRUE(s && s->tasks.size() == 1);
    StepView kq(*s);
    kq.lights[0].kq = kqForRadius(kq.lights[0], 5.0f);
    EXPECT_TRUE(taskMet(s->tasks[0], kq.context(*s, *l)));
    StepView kl(*s);
    kl.lights[0].kl = (1.0f / kl.lights[0].threshold - kl.lights[0].kc - kl.lights[0].kq * 25.0f) / 5.0f;
    EXPECT_NEAR(lightRadius(kl.lights[0]).radius, 5.0f, 0.01f);
    EXPECT_FALSE(taskMet(s->tasks[0], kl.context(*s, *l)));

    // camera_inside:4: cull back is the mode flip avoids for this light; none does not lose it.
    s = shipped(lib, "camera_inside:4", &l);
    ASSERT_TRUE(s && s->tasks.size() == 1);
    StepView back(*s);
    back.pipeline.cull = CullMode::None;
    EXPECT_FALSE(taskMet(s->tasks[0], back.context(*s, *l)));
    back.pipeline.cull = CullMode::Back;
    EXPECT_TRUE(taskMet(s->tasks[0], back.context(*s, *l)));

    // depth_blit:4: the copy off, not the blit.
    s = shipped(lib, "depth_blit:4", &l);
    ASSERT_TRUE(s && s->tasks.size() == 1);
    StepView off(*s);
    off.pipeline.depthCopy = DepthCopy::Blit;
    EXPECT_FALSE(taskMet(s->tasks[0], off.context(*s, *l)));
    off.pipeline.depthCopy = DepthCopy::Off;
    EXPECT_TRUE(taskMet(s->tasks[0], off.context(*s, *l)));

    // fullscreen_pass:3: light 06's intensity dragged to 3 (from 1.4918); not another light's, not
    // light 06's Kq (which also brightens it), not the intensity with another field changed too.
    s = shipped(lib, "fullscreen_pass:3", &l);
    ASSERT_TRUE(s && s->tasks.size() == 1);
    EXPECT_NEAR(s->state.lights[6].intensity, 1.4918f, 1e-4f);
    EXPECT_TRUE(s->state.litPinDiff);  // the step's diff shows the change
    StepView drag(*s);
    drag.lights[6].intensity = 3.0f;
    EXPECT_TRUE(taskMet(s->tasks[0], drag.context(*s, *l)));
    drag.lights[6].intensity = 2.0f;  // dragged, but not far enough
    EXPECT_FALSE(taskMet(s->tasks[0], drag.context(*s, *l)));
    StepView other(*s);
    other.lights[5].intensity = 3.0f;
    EXPECT_FALSE(taskMet(s->tasks[0], other.context(*s, *l)));
    StepView falloff(*s);
    falloff.lights[6].kq *= 0.5f;
    EXPECT_FALSE(taskMet(s->tasks[0], falloff.context(*s, *l)));
    falloff.lights[6].intensity = 3.0f;
    EXPECT_FALSE(taskMet(s->tasks[0], falloff.context(*s, *l)));

    // position_from_depth:2: a pixel of the region with the largest error, locked.
    s = shipped(lib, "position_from_depth:2", &l);
    ASSERT_TRUE(s && s->tasks.size() == 1);
    StepView px(*s);
    glm::vec4 const r = s->tasks[0].region;
    px.pixel = glm::ivec2((r.x + r.z) * 0.5f, (r.y + r.w) * 0.5f);
    EXPECT_TRUE(taskMet(s->tasks[0], px.context(*s, *l)));
    px.pixel = glm::ivec2(int(r.x), int(r.w) + 1);  // just below it
    EXPECT_FALSE(taskMet(s->tasks[0], px.context(*s, *l)));
}

}  // namespace
