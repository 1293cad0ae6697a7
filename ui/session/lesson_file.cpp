// Lesson files: reading (each step's state goes through the session parser) and the lesson
// folder. Every message names the file and the field. The field readers, a step's claim and its
// A/B: lesson_file_fields.cpp. Writing: lesson_file_write.cpp.
#include "session/lesson_file.h"

#include "core/pipeline_fields.h"
#include "model/lesson_claims.h"
#include "model/lesson_tasks.h"
#include "model/lesson_text.h"
#include "scene/default_scene.h"
#include "session/atomic_file.h"
#include "session/lesson_file_fields.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <stdexcept>

namespace gbl::ui {

using nlohmann::json;
namespace fs = std::filesystem;
using namespace lesson_fields;

namespace {

Camera const& defaultCamera() {
    // The default scene's own view, built once: lessons start where the editor starts.
    static Camera const camera = makeDefaultScene({0}).camera.value_or(Camera{});
    return camera;
}

// The session parser's messages start with the label and ": "; the field path follows.
std::string sessionField(std::string const& error) {
    std::string const prefix = "@: ";
    return error.rfind(prefix, 0) == 0 ? error.substr(prefix.size()) : error;
}

}  // namespace

// A step's whole state: the session the default scene starts with, patched by the lesson's
// setup and the step, then read by parseSession so every session rule (and every pipeline
// setting the session knows) applies. `path` names the step in messages.
Session lesson_fields::readState(json const& state, std::string const& path, glm::vec3* lookAt, bool* hasLookAt) {
    Session base;
    base.camera = defaultCamera();
    int lights = 32;
    if (auto it = state.find("scene"); it != state.end()) {
        knownFields(*it, path + ".scene", {"lights", "glass"});
        if (auto n = it->find("lights"); n != it->end()) lights = integer(*n, path + ".scene.lights", 0, kMaxLights);
        if (auto g = it->find("glass"); g != it->end()) {
            if (!g->is_boolean()) fail(path + ".scene.glass", "must be true or false");
            base.defaultSceneGlass = g->get<bool>();
        }
    }
    base.defaultSceneLights = lights;
    base.lights = makeDefaultLights(lights);
    json j = json::parse(sessionToJson(base));
    if (auto it = state.find("lights"); it != state.end()) j["lights"] = *it;
    *hasLookAt = false;
    if (auto it = state.find("camera"); it != state.end()) {
        if (!it->is_object()) fail(path + ".camera", "must be an object");
        json cam = *it;
        if (auto la = cam.find("look_at"); la != cam.end()) {
            if (!la->is_array() || la->size() != 3 || !(*la)[0].is_number() || !(*la)[1].is_number() ||
                !(*la)[2].is_number())
                fail(path + ".camera.look_at", "must be an array of 3 numbers");
            *lookAt = {(*la)[0].get<float>(), (*la)[1].get<float>(), (*la)[2].get<float>()};
            *hasLookAt = true;
            cam.erase("look_at");
        }
        j["camera"].merge_patch(cam);
    }
    for (char const* key : {"pipeline", "viewers"})
        if (auto it = state.find(key); it != state.end()) {
            if (!it->is_object()) fail(path + "." + key, "must be an object");
            if (std::string_view(key) == "pipeline")
                mergePipeline(j[key], *it);
            else
                j[key].merge_patch(*it);
        }
    SessionLoad load = parseSession(j.dump(), "@");
    if (!load.session) fail(path + "." + sessionField(load.error), "");
    return *load.session;
}

namespace {

// Setup first, then the step: objects merge field by field, "lights" and "pixel" replace.
json mergedState(json const& setup, json const& step) {
    json out = setup.is_object() ? setup : json::object();
    for (char const* key : {"scene", "lights", "camera", "pipeline", "viewers", "selected_light", "viewer", "pixel"}) {
        auto it = step.find(key);
        if (it == step.end()) continue;
        if ((std::string_view(key) == "camera" || std::string_view(key) == "pipeline" ||
             std::string_view(key) == "viewers" || std::string_view(key) == "scene") &&
            it->is_object() && out.contains(key) && out[key].is_object()) {
            if (std::string_view(key) == "pipeline")
                lesson_fields::mergePipeline(out[key], *it);
            else
                out[key].merge_patch(*it);
        } else
            out[key] = *it;
    }
    return out;
}

LessonSnapshot snapshotOf(json const& state, std::string const& path, int* defaultLights = nullptr,
                          bool* glass = nullptr);

// "predict": {"prompt", "choices" + "correct" | "number" + "tolerance", "explain", "before"}.
LessonPrediction readPrediction(json const& j, std::string const& path, json const& state) {
    knownFields(j, path, {"prompt", "choices", "correct", "number", "tolerance", "explain", "before"});
    LessonPrediction p;
    p.prompt = text(j, "prompt", path);
    p.explain = text(j, "explain", path);
    auto choices = j.find("choices");
    auto numberIt = j.find("number");
    if ((choices == j.end()) == (numberIt == j.end()))
        fail(path, "must have either choices (with correct) or number (with tolerance)");
    if (choices != j.end()) {
        if (!choices->is_array() || choices->size() < 2 || choices->size() > 6)
            fail(path + ".choices", "must be an array of 2 to 6 strings");
        for (std::size_t i = 0; i < choices->size(); ++i) {
            json const wrap = {{"c", (*choices)[i]}};
            p.choices.push_back(text(wrap, "c", path + ".choices[" + std::to_string(i) + "]"));
        }
        auto c = j.find("correct");
        if (c == j.end()) fail(path + ".correct", "is missing (the index of the right choice)");
        p.correct = integer(*c, path + ".correct", 0, int(p.choices.size()) - 1);
        if (j.contains("tolerance")) fail(path + ".tolerance", "is only for a number prediction");
    } else {
        p.number = number(*numberIt, path + ".number", -1e9f, 1e9f);
        auto t = j.find("tolerance");
        if (t == j.end()) fail(path + ".tolerance", "is missing (how far from number still counts as right)");
        p.tolerance = number(*t, path + ".tolerance", 0.0f, 1e9f);
        if (j.contains("correct")) fail(path + ".correct", "is only for a multiple-choice prediction");
    }
    if (auto b = j.find("before"); b != j.end()) {
        knownFields(*b, path + ".before",
                    {"scene", "lights", "camera", "pipeline", "viewers", "selected_light", "viewer"});
        // The step's state with these fields changed, merged like a step over the setup.
        bool glassBefore = false, glassStep = false;
        p.before = snapshotOf(mergedState(state, *b), path + ".before", nullptr, &glassBefore);
        snapshotOf(state, path, nullptr, &glassStep);
        // The editor shows a prediction's `before` on the step's scene: the glass stays as the step has it.
        if (glassBefore != glassStep)
            fail(path + ".before.scene.glass",
                 "cannot differ from the step's: a prediction changes the state, "
                 "not the scene");
        p.beforeJson = b->dump();
    }
    return p;
}

// "tasks": [{"kind", "goal", "hint", ...the kind's fields (taskKinds())}]: goals the editor
// checks live. A task already met in the step's own state asks for nothing and is refused.
std::vector<LessonTask> readTasks(json const& j, std::string const& path, LessonStep const& step,
                                  glm::ivec2 lessonSize) {
    if (!j.is_array() || j.empty()) fail(path, "must be an array of at least one task");
    std::vector<LessonTask> tasks;
    for (std::size_t i = 0; i < j.size(); ++i) {
        std::string const at = path + "[" + std::to_string(i) + "]";
        json const& t = j[i];
        if (!t.is_object()) fail(at, "must be an object");
        std::string kinds;
        for (TaskKindInfo const& k : taskKinds()) kinds += (kinds.empty() ? "" : ", ") + std::string(k.name);
        auto kindIt = t.find("kind");
        if (kindIt == t.end()) fail(at + ".kind", "is missing (one of " + kinds + ")");
        TaskKindInfo const* info = kindIt->is_string() ? findTaskKind(kindIt->get<std::string>()) : nullptr;
        if (!info) fail(at + ".kind", "must be one of " + kinds + " (got " + kindIt->dump() + ")");
        for (auto it = t.begin(); it != t.end(); ++it) {
            std::string_view const key = it.key();
            bool const known =
                key == "kind" || key == "goal" || key == "hint" ||
                std::find(info->fields.begin(), info->fields.end(), key) != info->fields.end() ||
                std::find(info->optionalFields.begin(), info->optionalFields.end(), key) != info->optionalFields.end();
            if (!known) fail(at + "." + it.key(), "is not a field of a " + std::string(info->name) + " task");
        }
        for (std::string_view key : info->fields)
            if (!t.contains(key))
                fail(at + "." + std::string(key), "is missing (a " + std::string(info->name) + " task needs it)");
        LessonTask task;
        task.kind = info->kind;
        task.goal = text(t, "goal", at);
        task.hint = text(t, "hint", at);
        switch (info->kind) {
            case TaskKind::LightField: {
                task.light = integer(t["light"], at + ".light", 0, int(step.state.lights.size()) - 1);
                std::string names;
                for (LightField const& f : kLightFields) names += std::string(f.name) + ", ";
                names += "radius";
                json const& field = t["field"];
                if (!field.is_string() || !isTaskLightField(field.get<std::string>()))
                    fail(at + ".field", "must be one of " + names + " (got " + field.dump() + ")");
                task.field = field.get<std::string>();
                for (char const* key : {"value", "tolerance"}) {
                    TaskNumberField const& n = taskNumberField(key);
                    task.*n.member = number(t[key], at + "." + key, n.min, n.max);
                }
                if (auto only = t.find("only_changed"); only != t.end()) {
                    if (!only->is_array() || only->empty())
                        fail(at + ".only_changed", "must be an array of at least one light field name");
                    for (std::size_t k = 0; k < only->size(); ++k) {
                        json const& n = (*only)[k];
                        if (!n.is_string() || !findLightField(n.get<std::string>()))
                            fail(at + ".only_changed[" + std::to_string(k) + "]",
                                 "must be a field of kLightFields (got " + n.dump() + ")");
                        task.onlyChanged.push_back(n.get<std::string>());
                    }
                }
                break;
            }
            case TaskKind::Setting: {
                json const& name = t["setting"];
                PipelineField const* f = name.is_string() ? findPipelineField(name.get<std::string>()) : nullptr;
                if (!f) {
                    std::string names;
                    for (PipelineField const& p : pipelineFields())
                        names += (names.empty() ? "" : ", ") + std::string(p.name);
                    fail(at + ".setting", "must be a pipeline setting: one of " + names + " (got " + name.dump() + ")");
                }
                task.setting = std::string(f->name);  // an old name ("blit") is read as the field's name
                json const& v = t["value"];
                std::string const value = v.is_string()    ? v.get<std::string>()
                                          : v.is_boolean() ? (v.get<bool>() ? "1" : "0")
                                                           : v.dump();
                auto const parsed = parseFieldValue(*f, value);
                if (!parsed) fail(at + ".value", v.dump() + " is not a value of " + task.setting);
                task.value = *parsed;
                if (auto tol = t.find("tolerance"); tol != t.end()) {
                    if (f->kind != SettingKind::Number) fail(at + ".tolerance", "is only for a number setting");
                    TaskNumberField const& n = taskNumberField("tolerance");
                    task.tolerance = number(*tol, at + ".tolerance", n.min, n.max);
                }
                break;
            }
            case TaskKind::Pixel: {
                json const& r = t["region"];
                if (!r.is_array() || r.size() != 4) fail(at + ".region", "must be [x0, y0, x1, y1] in frame pixels");
                glm::vec2 const hi = glm::vec2(lessonSize) - 1.0f;
                for (int c = 0; c < 4; ++c)
                    task.region[c] = float(integer(r[std::size_t(c)], at + ".region[" + std::to_string(c) + "]", 0,
                                                   int(c % 2 == 0 ? hi.x : hi.y)));
                if (task.region.x > task.region.z || task.region.y > task.region.w)
                    fail(at + ".region", "must have x0 <= x1 and y0 <= y1 (got " + r.dump() + ")");
                break;
            }
        }
        // The step as it is shown, at the lesson's own size: the goal must still be ahead.
        TaskContext ctx;
        ctx.lights = step.state.lights;
        ctx.stepLights = step.state.lights;
        ctx.pipeline = &step.state.pipeline;
        ctx.pixelLocked = step.state.pixel.has_value();
        if (step.state.pixel) ctx.pixel = lessonPixel(*step.state.pixel, lessonSize);
        ctx.frameSize = lessonSize;
        ctx.lessonSize = lessonSize;
        if (taskMet(task, ctx)) fail(at, "is already met in the step's own state: a task must ask for a change");
        tasks.push_back(std::move(task));
    }
    return tasks;
}

LessonStep readStep(json const& j, std::string const& path, json const& setup, std::string const& lessonId,
                    glm::ivec2 lessonSize, bool gltfScene) {
    knownFields(
        j, path,
        {"title", "look", "equation", "question", "answer", "predict", "tasks", "scene", "lights", "camera", "pipeline",
         "viewers", "selected_light", "viewer", "pixel", "claim", "ab", "light_by_light", "lit_pin"});
    LessonStep step;
    step.text.title = text(j, "title", path);
    step.text.look = text(j, "look", path);
    step.text.equation = text(j, "equation", path);
    step.text.question = text(j, "question", path);
    if (!j.contains("answer"))
        fail(path + ".answer", "is missing: step \"" + step.text.title + "\" of lesson " + lessonId +
                                   " asks a question and every question needs an answer the student can reveal");
    step.text.answer = text(j, "answer", path);
    json const state = mergedState(setup, j);
    if (gltfScene) {
        // The default scene's lights and camera are placed for the default scene, not for another.
        if (!state.contains("lights"))
            fail(path + ".lights",
                 "is missing: a lesson on a glTF scene (\"scene\") names its lights, in setup or "
                 "in each step");
        if (!state.contains("camera") || !state["camera"].is_object() || !state["camera"].contains("position"))
            fail(path + ".camera.position",
                 "is missing: a lesson on a glTF scene (\"scene\") places its camera, in "
                 "setup or in each step");
    }
    step.state = snapshotOf(state, path, &step.defaultSceneLights, &step.defaultSceneGlass);
    if (gltfScene && step.defaultSceneGlass)
        fail(path + ".scene.glass",
             "stands its panes in the default scene and cannot be used in a lesson on a glTF "
             "scene (\"scene\")");
    if (auto it = j.find("ab"); it != j.end()) step.state.ab = readAb(*it, path + ".ab", step.state.pipeline);
    if (auto it = j.find("light_by_light"); it != j.end())
        step.state.lightByLight = readLightByLight(*it, path + ".light_by_light", int(step.state.lights.size()));
    if (auto it = j.find("lit_pin"); it != j.end()) {
        if (!it->is_boolean()) fail(path + ".lit_pin", "must be true or false");
        step.state.litPinDiff = it->get<bool>();
    }
    if (auto it = j.find("claim"); it != j.end()) step.claim = readClaim(*it, path + ".claim", state, step);
    if (auto it = j.find("predict"); it != j.end()) step.predict = readPrediction(*it, path + ".predict", state);
    if (auto it = j.find("tasks"); it != j.end()) {
        step.tasks = readTasks(*it, path + ".tasks", step, lessonSize);
        step.tasksJson = it->dump();
    }
    return step;
}

// The whole state of a step (or of a prediction's `before`) from its merged JSON.
LessonSnapshot snapshotOf(json const& state, std::string const& path, int* defaultLights, bool* glass) {
    LessonSnapshot out;
    glm::vec3 lookAt{0.0f};
    bool hasLookAt = false;
    Session const s = readState(state, path, &lookAt, &hasLookAt);
    if (defaultLights) *defaultLights = s.defaultSceneLights;
    if (glass) *glass = s.defaultSceneGlass;
    out.camera = s.camera;
    if (hasLookAt) {
        if (glm::length(lookAt - s.camera.position) < 1e-4f)
            fail(path + ".camera.look_at", "must differ from camera.position");
        out.camera.lookAt(lookAt);
        if (std::abs(out.camera.pitchDegrees) > 89.0f)
            fail(path + ".camera.look_at", "is straight above or below the camera (pitch must stay within 89 degrees)");
    }
    out.lights = s.lights;
    out.pipeline = s.pipeline;
    out.viewers = s.viewers;
    out.animation = {};
    if (auto it = state.find("selected_light"); it != state.end())
        out.selectedLight = integer(*it, path + ".selected_light", -1, int(s.lights.size()) - 1);
    if (auto it = state.find("viewer"); it != state.end()) {
        auto const v = it->is_string() ? enumFromName<ViewerKind>(kViewerNames, it->get<std::string>()) : std::nullopt;
        if (!v)
            fail(path + ".viewer",
                 "must be one of position, normal, albedo, specular or depth (got " + it->dump() + ")");
        out.activeViewer = int(*v);
    }
    if (auto it = state.find("pixel"); it != state.end()) {
        if (!it->is_array() || it->size() != 2) fail(path + ".pixel", "must be an array of 2 numbers");
        glm::vec2 p;
        for (int i = 0; i < 2; ++i)
            p[i] = number((*it)[std::size_t(i)], path + ".pixel[" + std::to_string(i) + "]", 0.0f, 1.0f);
        out.pixel = p;
    }
    return out;
}

// "scene": a glTF file, found in the lesson's folder first, then in the shared models folder.
std::string findLessonScene(json const& j, fs::path const& folder) {
    if (!j.is_string() || j.get<std::string>().empty())
        fail("scene", "must be the path of a glTF file (.gltf or .glb)");
    std::string const name = j.get<std::string>();
    std::string ext = fs::path(name).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext != ".gltf" && ext != ".glb") fail("scene", "must name a .gltf or .glb file (got " + j.dump() + ")");
    std::vector<fs::path> tried;
    if (fs::path(name).is_absolute()) {
        tried.push_back(name);
    } else {
        tried.push_back(folder / name);
        tried.push_back(fs::path(sharedModelsDir()) / name);
    }
    std::error_code ec;
    for (fs::path const& p : tried)
        if (fs::is_regular_file(p, ec)) return p.lexically_normal().string();
    std::string where;
    for (fs::path const& p : tried) where += (where.empty() ? "" : " nor ") + p.lexically_normal().string();
    fail("scene", j.dump() + " is not a file: neither " + where + " exists" +
                      (tried.size() > 1 ? " (a scene is looked for in the lesson's folder, then in the shared models "
                                          "folder; GBL_SHARED_GLTF_DIR names another)"
                                        : ""));
}

Lesson readLesson(json const& j, fs::path const& folder) {
    if (!j.is_object()) fail("the file", "must hold a JSON object");
    auto fmt = j.find("format");
    if (fmt == j.end()) fail("format", "is missing");
    if (!fmt->is_string() || fmt->get<std::string>() != kLessonFormat)
        fail("format", "must be \"" + std::string(kLessonFormat) + "\" (got " + fmt->dump() +
                           "); this is not a gbuffer-lab lesson");
    auto ver = j.find("version");
    if (ver == j.end()) fail("version", "is missing");
    if (!ver->is_number_integer() || ver->get<long long>() != kLessonVersion)
        fail("version", ver->dump() + " is not supported; this program reads lesson version " +
                            std::to_string(kLessonVersion) +
                            (ver->is_number_integer() && ver->get<long long>() == 1
                                 ? " (version 2 adds an \"answer\" to every step: add one and set \"version\": 2)"
                                 : ""));
    knownFields(j, "", {"format", "version", "id", "title", "summary", "scene", "size", "setup", "steps"});
    Lesson lesson;
    auto id = j.find("id");
    if (id == j.end()) fail("id", "is missing");
    if (!id->is_string() || id->get<std::string>().empty() ||
        id->get<std::string>().find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_-") != std::string::npos)
        fail("id", "must be lower-case letters, digits, '_' or '-' (got " + id->dump() + ")");
    lesson.id = id->get<std::string>();
    lesson.title = text(j, "title", "");
    if (j.contains("summary")) lesson.summary = text(j, "summary", "", false);
    if (auto size = j.find("size"); size != j.end()) {
        if (!size->is_array() || size->size() != 2) fail("size", "must be [width, height]");
        lesson.width = integer((*size)[0], "size[0]", 16, 8192);
        lesson.height = integer((*size)[1], "size[1]", 16, 8192);
    }
    if (auto scene = j.find("scene"); scene != j.end()) {
        lesson.scene = scene->is_string() ? scene->get<std::string>() : "";
        lesson.scenePath = findLessonScene(*scene, folder);
    }
    json setup = json::object();
    if (auto s = j.find("setup"); s != j.end()) {
        knownFields(*s, "setup",
                    {"scene", "lights", "camera", "pipeline", "viewers", "selected_light", "viewer", "pixel"});
        setup = *s;
        glm::vec3 ignored;
        bool has = false;
        readState(setup, "setup", &ignored, &has);  // its own errors name the setup, not a step
    }
    auto steps = j.find("steps");
    if (steps == j.end()) fail("steps", "is missing");
    if (!steps->is_array() || steps->empty()) fail("steps", "must be an array of at least one step");
    for (std::size_t i = 0; i < steps->size(); ++i)
        lesson.steps.push_back(readStep((*steps)[i], "steps[" + std::to_string(i) + "]", setup, lesson.id,
                                        {lesson.width, lesson.height}, !lesson.scenePath.empty()));
    return lesson;
}

}  // namespace

std::string lessonStepScene(Lesson const& lesson, int step) {
    if (!lesson.scenePath.empty()) return lesson.scenePath;
    return lesson.steps.at(std::size_t(step)).defaultSceneGlass ? std::string(kDefaultSceneGlass) : "default";
}

LessonLoad parseLesson(std::string_view source, std::string const& fileLabel) {
    LessonLoad out;
    json j;
    try {
        j = json::parse(source.begin(), source.end());
    } catch (json::exception const& e) {
        std::string what = e.what();
        if (auto const close = what.find("] "); what.rfind("[json.exception", 0) == 0 && close != std::string::npos)
            what = what.substr(close + 2);
        out.error = fileLabel + ": not valid JSON: " + what;
        return out;
    }
    try {
        out.lesson = readLesson(j, fs::path(fileLabel).parent_path());
    } catch (FieldError const& e) {
        std::string what = e.what();
        while (!what.empty() && what.back() == ' ') what.pop_back();
        if (what.rfind(".", 0) == 0) what = what.substr(1);
        out.error = fileLabel + ": " + what;
    } catch (json::exception const& e) {
        out.error = fileLabel + ": " + e.what();
    }
    return out;
}

LessonLoad loadLesson(std::string const& path) {
    std::string error;
    auto text = readWholeFile(path, &error);
    if (!text) return {std::nullopt, "cannot read lesson: " + error};
    LessonLoad load = parseLesson(*text, path);
    if (load.lesson) load.lesson->path = path;
    return load;
}

}  // namespace gbl::ui
