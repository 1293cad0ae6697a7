// Every shipped lesson has something the student does that the editor checks (the four that had none
// end with it): a task, unmet as its step opens, met by the intended action and not by a wrong one.
#include "core/pipeline_fields.h"
#include "model/lesson_tasks.h"
#include "session/lesson_file.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

using namespace gbl;
using namespace gbl::ui;

namespace {

LessonLibrary const& shipped() {
    static LessonLibrary const lib = loadLessonDir(defaultLessonDir());
    return lib;
}

Lesson const& lesson(std::string const& id) {
    for (Lesson const& l : shipped().lessons)
        if (l.id == id) return l;
    throw std::runtime_error("no shipped lesson " + id);
}

// The checklist of `step` over `pipeline` (the step's lights, its pixel locked at the lesson's size).
std::vector<bool> met(Lesson const& l, LessonStep const& step, PipelineSettings const& pipeline) {
    TaskContext c;
    c.lights = step.state.lights;
    c.stepLights = step.state.lights;
    c.pipeline = &pipeline;
    c.frameSize = c.lessonSize = {l.width, l.height};
    std::vector<bool> out;
    for (LessonTask const& t : step.tasks) out.push_back(taskMet(t, c));
    return out;
}

// `pipeline` with the setting `name` set to `value` as a lesson file writes it.
PipelineSettings with(PipelineSettings p, std::string_view name, std::string_view value) {
    PipelineField const* f = findPipelineField(name);
    EXPECT_TRUE(f) << name;
    if (!f) return p;
    auto v = parseFieldValue(*f, std::string(value));
    EXPECT_TRUE(v) << name << " " << value;
    if (v) f->set(p, *v);
    return p;
}

TEST(LessonEndingTasks, EveryLessonHasATask) {
    ASSERT_TRUE(shipped().errors.empty()) << shipped().errors.front();
    ASSERT_GE(shipped().lessons.size(), 10u);
    for (Lesson const& l : shipped().lessons) {
        int tasks = 0;
        for (LessonStep const& s : l.steps) {
            tasks += int(s.tasks.size());
            for (bool m : met(l, s, s.state.pipeline)) EXPECT_FALSE(m) << l.id << ": a task already met";
        }
        EXPECT_GT(tasks, 0) << l.id << " has no task";
    }
}

struct Case {
    std::string lesson;
    char const* setting;
    char const* right;
    char const* wrong;
};

// The four lessons that had no task: one setting each (executed_vs_lit has two, done in order).
TEST(LessonEndingTasks, TheNewTasksAreMetByTheIntendedSettingOnly) {
    for (Case const& k :
         {Case{"gbuffer", "view", "specular_light", "diffuse_light"}, Case{"tiled", "mode", "clustered", "quad"},
          Case{"forward_vs_deferred", "layout", "packed", "naive8"}}) {
        Lesson const& l = lesson(k.lesson);
        LessonStep const& step = l.steps.back();
        ASSERT_EQ(step.tasks.size(), 1u) << k.lesson;
        EXPECT_EQ(step.tasks[0].setting, k.setting) << k.lesson;
        EXPECT_TRUE(met(l, step, with(step.state.pipeline, k.setting, k.right))[0]) << k.lesson;
        EXPECT_FALSE(met(l, step, with(step.state.pipeline, k.setting, k.wrong))[0]) << k.lesson;
    }
    Lesson const& l = lesson("executed_vs_lit");
    LessonStep const& step = l.steps.back();
    ASSERT_EQ(step.tasks.size(), 2u);
    PipelineSettings const volumes = with(step.state.pipeline, "mode", "volumes");
    EXPECT_EQ(met(l, step, volumes), (std::vector<bool>{true, false}));  // step 2's cull front is not it
    EXPECT_EQ(met(l, step, with(volumes, "cull", "stencil")), (std::vector<bool>{true, true}));
    EXPECT_EQ(met(l, step, with(volumes, "cull", "flip")), (std::vector<bool>{true, false}));
}

// msaa:5 (issue 47), from 2 samples lit resolve-first: 4 samples, then the strategy with no halo that
// lights only the complex pixels per sample; per-sample (no halo, every pixel per sample) is not it.
// transparency:2: the depth copy off, not the shader copy (which hides the glass as the blit does).
TEST(LessonEndingTasks, TheMsaaAndGlassTasksAreMetByTheIntendedSettingsOnly) {
    Lesson const& l = lesson("msaa");
    LessonStep const& step = l.steps.back();
    ASSERT_EQ(step.tasks.size(), 2u);
    PipelineSettings const four = with(step.state.pipeline, "msaa", "4");
    EXPECT_EQ(met(l, step, four), (std::vector<bool>{true, false}));
    EXPECT_EQ(met(l, step, with(four, "msaa_lighting", "edges")), (std::vector<bool>{true, true}));
    EXPECT_EQ(met(l, step, with(four, "msaa_lighting", "per-sample")), (std::vector<bool>{true, false}));
    EXPECT_EQ(met(l, step, with(step.state.pipeline, "msaa", "8")), (std::vector<bool>{false, false}));
    Lesson const& t = lesson("transparency");
    LessonStep const& glass = t.steps.at(1);
    ASSERT_EQ(glass.tasks.size(), 1u);
    EXPECT_TRUE(met(t, glass, with(glass.state.pipeline, "depth_copy", "off"))[0]);
    EXPECT_FALSE(met(t, glass, with(glass.state.pipeline, "depth_copy", "shader"))[0]);
}

// light_volumes:2: the setting multiplies the mesh's enclosing scale, so the smallest scale that
// loses nothing is 1 (its diff against B is black); 1.03, the enclosing scale itself, is not it.
TEST(LessonEndingTasks, TheVolumeScaleTaskWantsOne) {
    Lesson const& l = lesson("light_volumes");
    LessonStep const& step = l.steps.at(1);
    ASSERT_EQ(step.tasks.size(), 1u);
    EXPECT_TRUE(met(l, step, with(step.state.pipeline, "volume_scale", "1"))[0]);
    EXPECT_FALSE(met(l, step, with(step.state.pipeline, "volume_scale", "1.03"))[0]);
    EXPECT_FALSE(met(l, step, with(step.state.pipeline, "volume_scale", "0.95"))[0]);
}

// four_ways ends on tiled against Forward+ in the tile view: the task is switching A to forward+
// (no G-buffer, the same lists); plain forward, which lists nothing, is not it, nor is clustered.
TEST(LessonEndingTasks, TheFourWaysTaskWantsForwardPlus) {
    Lesson const& l = lesson("four_ways");
    LessonStep const& step = l.steps.back();
    ASSERT_EQ(step.tasks.size(), 1u);
    EXPECT_EQ(step.state.pipeline.mode, LightingMode::Tiled);
    EXPECT_TRUE(met(l, step, with(step.state.pipeline, "mode", "forward+"))[0]);
    EXPECT_FALSE(met(l, step, with(step.state.pipeline, "mode", "forward"))[0]);
    EXPECT_FALSE(met(l, step, with(step.state.pipeline, "mode", "clustered"))[0]);
}

}  // namespace
