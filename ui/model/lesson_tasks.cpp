// Lesson tasks: the table of kinds, their checks, and the checklist's progress and hint clock.
#include "model/lesson_tasks.h"

#include "core/light_math.h"
#include "core/pipeline_fields.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gbl::ui {

namespace {

constexpr std::string_view kRadius = "radius";

bool lightFieldMet(LessonTask const& t, TaskContext const& ctx) {
    if (t.light < 0 || t.light >= int(ctx.lights.size())) return false;
    PointLight const& now = ctx.lights[std::size_t(t.light)];
    auto const v = taskLightFieldValue(now, t.field);
    if (!v || !(std::abs(double(*v) - t.value) <= t.tolerance)) return false;
    if (t.onlyChanged.empty()) return true;
    // "By changing only Kq": every other number of the light is still the step's. Untouched
    // values are the same floats, so exact equality is the test.
    if (t.light >= int(ctx.stepLights.size())) return false;
    PointLight const& was = ctx.stepLights[std::size_t(t.light)];
    for (LightField const& f : kLightFields) {
        bool const allowed = std::find(t.onlyChanged.begin(), t.onlyChanged.end(), f.name) != t.onlyChanged.end();
        if (!allowed && f.of(now) != f.of(was)) return false;
    }
    return now.kind == was.kind;
}

bool settingMet(LessonTask const& t, TaskContext const& ctx) {
    PipelineField const* f = findPipelineField(t.setting);
    if (!f || !ctx.pipeline) return false;
    return std::abs(f->get(*ctx.pipeline) - t.value) <= t.tolerance;
}

bool pixelMet(LessonTask const& t, TaskContext const& ctx) {
    if (!ctx.pixelLocked || !ctx.pixel || ctx.frameSize.x <= 0 || ctx.frameSize.y <= 0) return false;
    // The live pixel in the lesson's frame pixels, where the region is written.
    glm::ivec2 const size = ctx.lessonSize.x > 0 && ctx.lessonSize.y > 0 ? ctx.lessonSize : ctx.frameSize;
    glm::vec2 const p = glm::floor((glm::vec2(*ctx.pixel) + 0.5f) * glm::vec2(size) / glm::vec2(ctx.frameSize));
    return p.x >= t.region.x && p.y >= t.region.y && p.x <= t.region.z && p.y <= t.region.w;
}

constexpr std::array<std::string_view, 4> kLightFieldFields{"light", "field", "value", "tolerance"};
constexpr std::array<std::string_view, 1> kLightFieldOptional{"only_changed"};
constexpr std::array<std::string_view, 2> kSettingFields{"setting", "value"};
constexpr std::array<std::string_view, 1> kSettingOptional{"tolerance"};
constexpr std::array<std::string_view, 1> kPixelFields{"region"};

std::array<TaskKindInfo, 3> const kTaskKinds{{
    {TaskKind::LightField, "light_field", kLightFieldFields, kLightFieldOptional, lightFieldMet,
     "the light's `field` (a name of `kLightFields`, or `radius`) is `value` ± `tolerance`, and no field "
     "outside `only_changed` differs from the step's"},
    {TaskKind::Setting, "setting", kSettingFields, kSettingOptional, settingMet,
     "the pipeline setting `setting` (a name of `core/pipeline_fields.h`) is `value` (± `tolerance` for a number)"},
    {TaskKind::Pixel,
     "pixel",
     kPixelFields,
     {},
     pixelMet,
     "the inspector is locked on a pixel inside `region` [x0, y0, x1, y1], frame pixels at the lesson's `size`"},
}};

}  // namespace

std::span<TaskKindInfo const> taskKinds() {
    return kTaskKinds;
}

TaskKindInfo const* findTaskKind(std::string_view name) {
    for (TaskKindInfo const& k : kTaskKinds)
        if (k.name == name) return &k;
    return nullptr;
}

TaskKindInfo const& taskKindInfo(TaskKind kind) {
    for (TaskKindInfo const& k : kTaskKinds)
        if (k.kind == kind) return k;
    return kTaskKinds[0];
}

bool isTaskLightField(std::string_view name) {
    return name == kRadius || findLightField(name) != nullptr;
}

std::optional<float> taskLightFieldValue(PointLight const& light, std::string_view name) {
    if (name == kRadius) return lightRadius(light).radius;
    if (LightField const* f = findLightField(name)) return f->of(light);
    return std::nullopt;
}

bool taskMet(LessonTask const& task, TaskContext const& ctx) {
    return taskKindInfo(task.kind).met(task, ctx);
}

namespace {

// A number as the goal text shows it: "%g" with a float's digits.
std::string shown(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

// The tolerance of a number goal: `wanted`, but below half the change so the start stays unmet.
double toleranceFor(double wanted, double change) {
    double const half = std::abs(change) * 0.5;
    return wanted < half ? wanted : half * 0.5;
}

}  // namespace

std::vector<LessonTask> tasksFromChange(PipelineSettings const& from, PipelineSettings const& to,
                                        std::span<PointLight const> fromLights, std::span<PointLight const> toLights) {
    std::vector<LessonTask> tasks;
    for (PipelineField const& f : pipelineFields()) {
        double const a = f.get(from);
        double const b = f.get(to);
        if (a == b) continue;
        LessonTask t;
        t.kind = TaskKind::Setting;
        t.setting = std::string(f.name);
        t.value = b;
        if (f.kind == SettingKind::Number) t.tolerance = toleranceFor(0.01 * double(f.max - f.min), b - a);
        std::string const value = fieldScriptText(f, to);
        t.goal = "Set " + t.setting + " to " +
                 (f.kind == SettingKind::Number ? shown(b) + " ± " + shown(t.tolerance) : value) + ".";
        t.hint = "Pipeline window: " + std::string(f.help);
        tasks.push_back(std::move(t));
    }
    std::size_t const lights = std::min(fromLights.size(), toLights.size());
    for (std::size_t i = 0; i < lights; ++i) {
        std::vector<LightField const*> changed;
        for (LightField const& f : kLightFields)
            if (f.of(fromLights[i]) != f.of(toLights[i])) changed.push_back(&f);
        std::vector<std::string> names;
        for (LightField const* f : changed) names.emplace_back(f->name);
        std::string list;
        for (LightField const* f : changed) list += (list.empty() ? "" : ", ") + std::string(f->label);
        for (LightField const* f : changed) {
            double const a = f->of(fromLights[i]);
            double const b = f->of(toLights[i]);
            LessonTask t;
            t.kind = TaskKind::LightField;
            t.light = int(i);
            t.field = std::string(f->name);
            t.value = b;
            t.tolerance = toleranceFor(std::max(0.01, 0.02 * std::abs(b)), b - a);
            t.onlyChanged = names;
            t.goal = "Make light " + std::to_string(i) + "'s " + std::string(f->label) + " " + shown(b) + " ± " +
                     shown(t.tolerance) + ", changing only its " + list + ".";
            t.hint = "Lights window: select light " + std::to_string(i) + " and change its " + std::string(f->label) +
                     " (drag, or Ctrl+click to type).";
            tasks.push_back(std::move(t));
        }
    }
    return tasks;
}

std::vector<TaskProgress> startTasks(std::size_t count, double now) {
    return std::vector<TaskProgress>(count, TaskProgress{false, now, false});
}

void updateTasks(std::vector<TaskProgress>& progress, std::span<LessonTask const> tasks, TaskContext const& ctx,
                 double now) {
    progress.resize(tasks.size(), TaskProgress{false, now, false});
    for (std::size_t i = 0; i < tasks.size(); ++i) {
        TaskProgress& p = progress[i];
        bool const met = taskMet(tasks[i], ctx);
        if (p.met && !met) p.unmetSince = now;  // undone: the hint waits a full period again
        p.met = met;
        p.hint = !met && now - p.unmetSince >= kTaskHintSeconds;
    }
}

}  // namespace gbl::ui
