// Lesson files: writing a lesson (each step's state through the session writer) and appending a
// step to a lesson file. Reading: lesson_file.cpp.
#include "session/lesson_file.h"

#include "model/ab_compare.h"
#include "session/atomic_file.h"
#include "session/session.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace gbl::ui {

namespace fs = std::filesystem;

namespace {

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
    if (step.predict) {
        LessonPrediction const& p = *step.predict;
        nlohmann::ordered_json pj = {{"prompt", p.prompt}};
        if (!p.choices.empty()) {
            pj["choices"] = p.choices;
            pj["correct"] = p.correct;
        } else {
            pj["number"] = p.number;
            pj["tolerance"] = p.tolerance;
        }
        pj["explain"] = p.explain;
        if (!p.beforeJson.empty()) pj["before"] = nlohmann::ordered_json::parse(p.beforeJson);
        j["predict"] = pj;
    }
    if (!step.tasksJson.empty()) j["tasks"] = nlohmann::ordered_json::parse(step.tasksJson);
    return j;
}

}  // namespace

std::string lessonToJson(Lesson const& lesson) {
    nlohmann::ordered_json steps = nlohmann::ordered_json::array();
    for (auto const& s : lesson.steps) steps.push_back(stepJson(s));
    nlohmann::ordered_json j = {
        {"format", kLessonFormat}, {"version", kLessonVersion}, {"id", lesson.id},
        {"title", lesson.title},   {"summary", lesson.summary}, {"size", {lesson.width, lesson.height}},
        {"steps", steps}};
    return j.dump(2) + "\n";
}

std::optional<std::string> appendLessonStep(std::string const& path, LessonStep const& step) {
    Lesson lesson;
    std::error_code ec;
    if (fs::exists(path, ec)) {
        LessonLoad load = loadLesson(path);
        if (!load.lesson) return load.error;
        lesson = std::move(*load.lesson);
    } else {
        std::string id;
        for (char c : fs::path(path).stem().string()) {
            char const l = char(std::tolower(static_cast<unsigned char>(c)));
            id += (std::isalnum(static_cast<unsigned char>(l)) || l == '-') ? l : '_';
        }
        lesson.id = id.empty() ? "lesson" : id;
        lesson.title = "Lesson " + lesson.id;
    }
    lesson.steps.push_back(step);
    return writeFileAtomically(path, lessonToJson(lesson));
}

}  // namespace gbl::ui
