// Lesson files: writing a lesson (each step's state through the session writer) and appending a
// step to a lesson file. Reading: lesson_file.cpp.
#include "session/lesson_file.h"

#include "core/pipeline_fields.h"
#include "model/ab_compare.h"
#include "session/atomic_file.h"
#include "session/session.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace gbl::ui {

namespace fs = std::filesystem;

namespace {

// Values read as floats, written with a float's digits (1.03, not 1.0299999713897705).
double floatDigits(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.7g", v);
    return std::strtod(buf, nullptr);
}

nlohmann::ordered_json stepJson(LessonStep const& step) {
    Session s;
    s.defaultSceneLights = step.defaultSceneLights;
    s.camera = step.state.camera;
    s.lights = step.state.lights;
    s.pipeline = step.state.pipeline;
    s.viewers = step.state.viewers;
    auto const session = nlohmann::ordered_json::parse(sessionToJson(s));
    nlohmann::ordered_json j = {{"title", step.text.title},
                                {"look", step.text.look},
                                {"equation", step.text.equation},
                                {"question", step.text.question},
                                {"answer", step.text.answer},
                                {"scene", {{"lights", step.defaultSceneLights}}},
                                {"camera", session["camera"]},
                                {"lights", session["lights"]},
                                {"pipeline", session["pipeline"]},
                                {"viewers", session["viewers"]},
                                {"selected_light", step.state.selectedLight},
                                {"viewer", kViewerNames[std::size_t(std::clamp(step.state.activeViewer, 0, 4))]}};
    if (step.defaultSceneGlass) j["scene"]["glass"] = true;
    if (step.state.pixel) j["pixel"] = {step.state.pixel->x, step.state.pixel->y};
    if (step.state.ab) {
        nlohmann::ordered_json b = nlohmann::ordered_json::object();
        auto const fields = abFields();
        for (std::size_t i = 0; i < fields.size() && i < step.state.ab->overrides.size(); ++i) {
            if (!step.state.ab->overrides[i]) continue;
            AbField const& f = fields[i];
            double const v = f.get(step.state.ab->b);
            if (f.kind == AbFieldKind::Choice)
                b[std::string(f.name)] = std::string(f.choices[std::size_t(v)]);
            else if (f.kind == AbFieldKind::Toggle)
                b[std::string(f.name)] = v != 0.0;
            else
                b[std::string(f.name)] = v;
        }
        j["ab"] = {{"view", step.state.ab->view == AbView::Diff ? "diff" : "split"}, {"b", b}};
    }
    if (step.state.lightByLight)
        j["light_by_light"] = {{"light", step.state.lightByLight->light}, {"only", step.state.lightByLight->only}};
    if (step.state.litPinDiff) j["lit_pin"] = true;
    if (step.predict) j["predict"] = nlohmann::ordered_json::parse(predictionToJson(*step.predict));
    // The tasks as the file had them when it was read (its author's order and spelling); tasks made
    // in the editor have no text yet and are written from their fields.
    if (!step.tasksJson.empty()) {
        j["tasks"] = nlohmann::ordered_json::parse(step.tasksJson);
    } else if (!step.tasks.empty()) {
        j["tasks"] = nlohmann::ordered_json::array();
        for (LessonTask const& t : step.tasks) j["tasks"].push_back(nlohmann::ordered_json::parse(taskToJson(t)));
    }
    return j;
}

}  // namespace

std::string taskToJson(LessonTask const& task) {
    nlohmann::ordered_json j = {{"kind", taskKindInfo(task.kind).name}, {"goal", task.goal}, {"hint", task.hint}};
    switch (task.kind) {
        case TaskKind::LightField:
            j["light"] = task.light;
            j["field"] = task.field;
            j["value"] = floatDigits(task.value);
            j["tolerance"] = floatDigits(task.tolerance);
            if (!task.onlyChanged.empty()) j["only_changed"] = task.onlyChanged;
            break;
        case TaskKind::Setting: {
            j["setting"] = task.setting;
            PipelineField const* f = findPipelineField(task.setting);
            if (!f) break;  // parseLesson refuses the name; nothing sensible to write
            PipelineSettings s;
            f->set(s, task.value);
            if (f->kind == SettingKind::Choice)
                j["value"] = fieldScriptText(*f, s);
            else if (f->kind == SettingKind::Toggle)
                j["value"] = task.value != 0.0;
            else
                j["value"] = floatDigits(task.value);
            if (f->kind == SettingKind::Number && task.tolerance > 0.0) j["tolerance"] = floatDigits(task.tolerance);
            break;
        }
        case TaskKind::Pixel:
            j["region"] = {int(task.region.x), int(task.region.y), int(task.region.z), int(task.region.w)};
            break;
    }
    return j.dump();
}

std::string predictionToJson(LessonPrediction const& p) {
    nlohmann::ordered_json pj = {{"prompt", p.prompt}};
    if (!p.choices.empty()) {
        pj["choices"] = p.choices;
        pj["correct"] = p.correct;
    } else {
        pj["number"] = floatDigits(p.number);
        pj["tolerance"] = floatDigits(p.tolerance);
    }
    pj["explain"] = p.explain;
    if (!p.beforeJson.empty()) pj["before"] = nlohmann::ordered_json::parse(p.beforeJson);
    return pj.dump();
}

std::string lessonToJson(Lesson const& lesson) {
    nlohmann::ordered_json steps = nlohmann::ordered_json::array();
    for (auto const& s : lesson.steps) steps.push_back(stepJson(s));
    nlohmann::ordered_json j = {{"format", kLessonFormat},
                                {"version", kLessonVersion},
                                {"id", lesson.id},
                                {"title", lesson.title},
                                {"summary", lesson.summary}};
    if (!lesson.scene.empty()) j["scene"] = lesson.scene;
    j["size"] = {lesson.width, lesson.height};
    j["steps"] = steps;
    return j.dump(2) + "\n";
}

std::optional<std::string> appendLessonStep(std::string const& path, LessonStep const& step,
                                            std::string const& scenePath) {
    Lesson lesson;
    std::error_code ec;
    if (fs::exists(path, ec)) {
        LessonLoad load = loadLesson(path);
        if (!load.lesson) return load.error;
        lesson = std::move(*load.lesson);
        auto const same = [](std::string const& a, std::string const& b) {
            std::error_code e;
            return a == b || (!a.empty() && !b.empty() && fs::equivalent(a, b, e));
        };
        if (!same(lesson.scenePath, scenePath))
            return path + ": lesson " + lesson.id + " is on " +
                   (lesson.scenePath.empty() ? "the default scene" : "the scene " + lesson.scenePath) +
                   ", and the editor shows " + (scenePath.empty() ? "the default scene" : scenePath) +
                   ": a step is saved to a lesson on the scene it was set up on";
    } else {
        // Absolute: a path relative to the editor's folder means nothing beside the lesson file.
        if (!scenePath.empty()) lesson.scene = fs::absolute(scenePath, ec).lexically_normal().string();
        std::string id;
        for (char c : fs::path(path).stem().string()) {
            char const l = char(std::tolower(static_cast<unsigned char>(c)));
            id += (std::isalnum(static_cast<unsigned char>(l)) || l == '-') ? l : '_';
        }
        lesson.id = id.empty() ? "lesson" : id;
        lesson.title = "Lesson " + lesson.id;
    }
    lesson.steps.push_back(step);
    // The file is written only when it reads back as a lesson: a step the reader refuses (a task
    // already met, say) must not leave a file that no longer opens.
    std::string const text = lessonToJson(lesson);
    if (LessonLoad const check = parseLesson(text, path); !check.lesson) return "step not saved: " + check.error;
    return writeFileAtomically(path, text);
}

}  // namespace gbl::ui
