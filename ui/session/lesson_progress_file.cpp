// Reading and writing the course progress file (see lesson_progress_file.h).
#include "session/lesson_progress_file.h"

#include "session/atomic_file.h"
#include "session/config_dir.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace gbl::ui {

using nlohmann::json;

namespace {

// A whole number from 1 (the file's 1-based steps and tasks), or throws naming `path`.
int oneBased(json const& j, std::string const& path) {
    if (!j.is_number_integer() || j.get<long long>() < 1 || j.get<long long>() > 100000)
        throw std::runtime_error(path + " must be a whole number from 1");
    return int(j.get<long long>());
}

void onlyFields(json const& j, std::string const& path, std::initializer_list<char const*> known) {
    for (auto it = j.begin(); it != j.end(); ++it)
        if (std::find_if(known.begin(), known.end(), [&](char const* k) { return it.key() == k; }) == known.end())
            throw std::runtime_error(path + "." + it.key() + " is not a known field");
}

LessonProgress parseLesson(json const& j, std::string const& path) {
    if (!j.is_object()) throw std::runtime_error(path + " must be an object");
    onlyFields(j, path, {"at", "steps"});
    LessonProgress l;
    auto at = j.find("at");
    if (at == j.end()) throw std::runtime_error(path + ".at is missing");
    l.at = oneBased(*at, path + ".at") - 1;
    auto steps = j.find("steps");
    if (steps == j.end() || !steps->is_array()) throw std::runtime_error(path + ".steps must be an array");
    for (std::size_t i = 0; i < steps->size(); ++i) {
        json const& s = (*steps)[i];
        std::string const sp = path + ".steps[" + std::to_string(i) + "]";
        if (!s.is_object()) throw std::runtime_error(sp + " must be an object");
        onlyFields(s, sp, {"step", "tasks_done", "prediction"});
        auto step = s.find("step");
        if (step == s.end()) throw std::runtime_error(sp + ".step is missing");
        int const index = oneBased(*step, sp + ".step") - 1;
        if (l.steps.contains(index)) throw std::runtime_error(sp + ".step repeats step " + std::to_string(index + 1));
        StepProgress& p = l.steps[index];
        if (auto t = s.find("tasks_done"); t != s.end()) {
            if (!t->is_array()) throw std::runtime_error(sp + ".tasks_done must be an array of task numbers");
            for (std::size_t k = 0; k < t->size(); ++k) {
                int const task = oneBased((*t)[k], sp + ".tasks_done[" + std::to_string(k) + "]") - 1;
                auto at = std::lower_bound(p.tasksDone.begin(), p.tasksDone.end(), task);
                if (at == p.tasksDone.end() || *at != task) p.tasksDone.insert(at, task);
            }
        }
        if (auto pr = s.find("prediction"); pr != s.end()) {
            if (!pr->is_string() || (*pr != "right" && *pr != "wrong"))
                throw std::runtime_error(sp + ".prediction must be \"right\" or \"wrong\"");
            p.prediction = *pr == "right";
        }
    }
    return l;
}

}  // namespace

ProgressLoad parseProgress(std::string_view text, std::string const& fileLabel) {
    ProgressLoad load;
    try {
        json const j = json::parse(text.begin(), text.end());
        if (!j.is_object() || j.value("format", "") != kProgressFormat)
            throw std::runtime_error("format must be \"" + std::string(kProgressFormat) + "\"");
        if (j.value("version", 0) != kProgressVersion)
            throw std::runtime_error("version must be " + std::to_string(kProgressVersion));
        onlyFields(j, "file", {"format", "version", "lessons"});
        auto lessons = j.find("lessons");
        if (lessons == j.end() || !lessons->is_object()) throw std::runtime_error("lessons must be an object");
        for (auto it = lessons->begin(); it != lessons->end(); ++it)
            load.progress.lessons[it.key()] = parseLesson(it.value(), "lessons." + it.key());
    } catch (std::exception const& e) {
        load.progress = {};
        load.error = fileLabel + ": " + e.what();
    }
    return load;
}

ProgressLoad loadProgress(std::string const& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec) && !ec) {
        ProgressLoad load;
        load.missing = true;
        return load;
    }
    std::string error;
    std::optional<std::string> const text = readWholeFile(path, &error);
    if (!text) {
        ProgressLoad load;
        load.error = error;
        return load;
    }
    return parseProgress(*text, path);
}

std::string progressToJson(CourseProgress const& progress) {
    json lessons = json::object();
    for (auto const& [id, l] : progress.lessons) {
        json steps = json::array();
        for (auto const& [step, s] : l.steps) {
            json js = {{"step", step + 1}};
            if (!s.tasksDone.empty()) {
                json tasks = json::array();
                for (int t : s.tasksDone) tasks.push_back(t + 1);
                js["tasks_done"] = tasks;
            }
            if (s.prediction) js["prediction"] = *s.prediction ? "right" : "wrong";
            steps.push_back(js);
        }
        lessons[id] = {{"at", l.at + 1}, {"steps", steps}};
    }
    json const j = {{"format", std::string(kProgressFormat)}, {"version", kProgressVersion}, {"lessons", lessons}};
    return j.dump(2) + "\n";
}

std::optional<std::string> saveProgress(std::string const& path, CourseProgress const& progress) {
    return writeFileAtomically(path, progressToJson(progress));
}

std::optional<std::string> keepBrokenProgress(std::string const& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return std::nullopt;
    std::filesystem::rename(path, path + ".broken", ec);
    if (ec) return path + ": could not be moved aside to " + path + ".broken (" + ec.message() + ")";
    return std::nullopt;
}

std::optional<std::string> progressFilePath(std::string* why) {
    std::optional<std::string> const dir = configDir();
    if (!dir) {
        if (why) *why = "neither XDG_CONFIG_HOME nor HOME names a folder";
        return std::nullopt;
    }
    if (auto error = ensureConfigDir(*dir)) {
        if (why) *why = *error;
        return std::nullopt;
    }
    return configFile(*dir, std::string(kProgressFileName));
}

LessonShape lessonShape(Lesson const& lesson) {
    LessonShape shape;
    for (LessonStep const& s : lesson.steps) {
        shape.tasks.push_back(int(s.tasks.size()));
        shape.predicts.push_back(s.predict.has_value());
    }
    return shape;
}

}  // namespace gbl::ui
