// Lesson tasks: goals a step sets over the editor's state ("make the radius 5 ± 0.2 by changing
// only Kq", "find the cull mode that loses the light", "lock a pixel in this region"), checked live
// as a checklist, with a hint naming the tool once a task has stayed unmet for a while. Pure
// functions over plain values: no ImGui, no GL, tested on the CPU (tests/lesson_tasks_test.cpp).
#pragma once

#include "core/pipeline_settings.h"
#include "core/point_light.h"

#include <glm/glm.hpp>

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gbl::ui {

enum class TaskKind {
    LightField,  // a light's field (kLightFields, or its radius) equals a value within a tolerance
    Setting,     // a pipeline setting (core/pipeline_fields.h) equals a value
    Pixel,       // the inspector's locked pixel lies inside a region of the frame
};

// One task of a step, as read from its lesson file (session/lesson_file.cpp validates it).
struct LessonTask {
    TaskKind kind = TaskKind::LightField;
    std::string goal;  // the checklist line (placeholders allowed)
    std::string hint;  // shown after kTaskHintSeconds unmet: names the tool to use
    // light_field
    int light = 0;                         // index into the step's lights
    std::string field;                     // a kLightFields name, or "radius"
    std::vector<std::string> onlyChanged;  // the light's only fields that may differ from the step's (empty: any)
    // light_field and setting
    double value = 0.0;  // setting: the field's value as pipelineFields() carries it (a choice's index, 0/1)
    double tolerance = 0.0;
    // setting
    std::string setting;  // a pipelineFields() name
    // pixel: [x0, y0, x1, y1] in pixels of the lesson's frame size (top-left origin, inclusive),
    // scaled to the live frame so the region names the same surface at any viewport size.
    glm::vec4 region{0.0f};
};

// What a task is checked against: the editor now and the step as it was shown.
struct TaskContext {
    std::span<PointLight const> lights;      // the editor's lights now
    std::span<PointLight const> stepLights;  // the step's own lights (what "changed" is measured from)
    PipelineSettings const* pipeline = nullptr;
    bool pixelLocked = false;
    std::optional<glm::ivec2> pixel;  // the inspector's pixel, live-frame pixels
    glm::ivec2 frameSize{0};          // the live frame
    glm::ivec2 lessonSize{0};         // the lesson's `size`, which regions are written in
};

// The one table of task kinds: its name in lesson files, the fields it reads (besides kind,
// goal and hint; `optional` ones may be left out), the check, and one line of documentation.
// docs/lessons.md documents exactly these (tests/lesson_tasks_test.cpp).
struct TaskKindInfo {
    TaskKind kind;
    std::string_view name;
    std::span<std::string_view const> fields;
    std::span<std::string_view const> optionalFields;
    bool (*met)(LessonTask const&, TaskContext const&);
    std::string_view doc;
};
std::span<TaskKindInfo const> taskKinds();
TaskKindInfo const* findTaskKind(std::string_view name);
TaskKindInfo const& taskKindInfo(TaskKind kind);

// A task's numbers as lesson files give them: the key, the LessonTask member, the range a file may
// give, and the default (LessonTask{}'s: a setting task without `tolerance` wants the value exactly).
// A setting task's `value` is the setting's own (core/pipeline_fields.h), not this range.
struct TaskNumberField {
    std::string_view name;
    double LessonTask::*member = nullptr;
    float min = 0.0f, max = 0.0f;
    double defaultValue() const { return LessonTask{}.*member; }
};
inline constexpr std::array<TaskNumberField, 2> kTaskNumberFields{{
    {"value", &LessonTask::value, -1e6f, 1e6f},
    {"tolerance", &LessonTask::tolerance, 0.0f, 1e6f},
}};
inline TaskNumberField const& taskNumberField(std::string_view name) {
    for (TaskNumberField const& f : kTaskNumberFields)
        if (f.name == name) return f;
    return kTaskNumberFields[0];
}

// The fields a light_field task may name: kLightFields' names, then "radius" (lightRadius()).
bool isTaskLightField(std::string_view name);
std::optional<float> taskLightFieldValue(PointLight const& light, std::string_view name);

// Whether the task's goal holds in `ctx`.
bool taskMet(LessonTask const& task, TaskContext const& ctx);

// --- tasks made from an author's change -------------------------------------------------------

// The tasks that ask a student to make the change an author made from `from` to `to` ("Save this
// state as a step" with "Add tasks"): one `setting` task per pipeline setting that differs, and one
// `light_field` task per light field that differs (lights matched by index, only the lights both
// have), whose `only_changed` lists that light's changed fields. A number's tolerance is 1 % of the
// setting's range (2 % of the light field's value, at least 0.01), and always less than half the
// change, so the task is unmet in `from` and met in `to`. Goal and hint are written out (no
// placeholders). Empty when nothing the tasks can check changed.
std::vector<LessonTask> tasksFromChange(PipelineSettings const& from, PipelineSettings const& to,
                                        std::span<PointLight const> fromLights, std::span<PointLight const> toLights);

// --- progress and hints ----------------------------------------------------------------------

// About this long unmet (since the step showed, or since the task was last met) before its hint shows.
inline constexpr double kTaskHintSeconds = 45.0;

struct TaskProgress {
    bool met = false;
    double unmetSince = 0.0;  // when it was last seen unmet after being met, or the step showed
    bool hint = false;        // the hint is due
};

// A fresh checklist for `count` tasks shown at `now` (seconds).
std::vector<TaskProgress> startTasks(std::size_t count, double now);
// One evaluation at `now`: ticks what is met, and starts a task's hint clock again when it
// stops being met.
void updateTasks(std::vector<TaskProgress>& progress, std::span<LessonTask const> tasks, TaskContext const& ctx,
                 double now);

}  // namespace gbl::ui
