// The lesson commands: listing the lesson files, and rendering one step as `render` does.
#include "lesson_command.h"
#include "cli_options.h"

#include "cli_values.h"
#include "frame_export.h"
#include "lesson_render.h"
#include "model/lesson_claims.h"
#include "scene/default_scene.h"
#include "scene_setup.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace gbl {

namespace {

ui::LessonLibrary loadLibrary(std::optional<std::string> const& dir) {
    return ui::loadLessonDir(dir.value_or(ui::defaultLessonDir()));
}

}  // namespace

void addLessonsOptions(CLI::App& sub, LessonsOptions& o) {
    sub.add_flag("--json", o.json, "Write the list as JSON");
    cli::addShared(sub, cli::kLessonsDir, o.dir);
}

int runLessons(LessonsOptions const& o) {
    ui::LessonLibrary const lib = loadLibrary(o.dir);
    if (o.json) {
        nlohmann::ordered_json out = nlohmann::ordered_json::array();
        for (auto const& l : lib.lessons) {
            nlohmann::ordered_json steps = nlohmann::ordered_json::array();
            for (std::size_t i = 0; i < l.steps.size(); ++i) {
                auto const& st = l.steps[i];
                // Tasks and predictions as the lesson file writes them, so a tool reads one format.
                nlohmann::ordered_json tasks = nlohmann::ordered_json::array();
                for (ui::LessonTask const& t : st.tasks)
                    tasks.push_back(nlohmann::ordered_json::parse(ui::taskToJson(t)));
                nlohmann::ordered_json step = {
                    {"step", i + 1},
                    {"title", st.text.title},
                    {"claim", st.claim ? std::string(ui::claimKindInfo(st.claim->kind).name) : ""},
                    {"question", st.text.question},
                    {"answer", st.text.answer},
                    {"tasks", tasks}};
                if (st.predict) step["predict"] = nlohmann::ordered_json::parse(ui::predictionToJson(*st.predict));
                steps.push_back(step);
            }
            nlohmann::ordered_json lesson = {{"id", l.id}, {"title", l.title}, {"file", l.path}};
            if (!l.scenePath.empty()) lesson["scene"] = l.scenePath;
            lesson["steps"] = steps;
            out.push_back(lesson);
        }
        std::printf("%s\n", out.dump(2).c_str());
    } else {
        for (auto const& l : lib.lessons) {
            std::printf("%s  %s (%zu steps%s%s)\n", l.id.c_str(), l.title.c_str(), l.steps.size(),
                        l.scenePath.empty() ? "" : ", scene ", l.scenePath.c_str());
            for (std::size_t i = 0; i < l.steps.size(); ++i)
                std::printf("  %s:%zu  %s\n", l.id.c_str(), i + 1, l.steps[i].text.title.c_str());
        }
    }
    for (auto const& e : lib.errors) std::fprintf(stderr, "gbuffer-lab lessons: %s\n", e.c_str());
    return lib.errors.empty() ? 0 : 2;
}

int runRenderLesson(RenderOptions const& o) {
    auto bad = [](std::string const& m) {
        std::fprintf(stderr, "gbuffer-lab render: %s\n", m.c_str());
        return 2;
    };
    for (char const* name : {cli::kScene.name, cli::kLights.name, "--time"})
        if (o.given.count(name)) return bad(std::string(name) + " cannot be combined with --lesson (the step sets it)");
    if (auto const name = firstPipelineOptionGiven(o.given))
        return bad(*name + " cannot be combined with --lesson (the step sets it)");
    if (o.sessionPath) return bad(std::string(cli::kSession.name) + " cannot be combined with --lesson");
    // A broken lesson file is an error even when another lesson is asked for: the folder is one unit.
    ui::LessonLibrary const lib = loadLibrary(o.lessonsDir);
    if (!lib.errors.empty()) return bad(lib.errors.front());
    ui::LessonRef const ref = ui::findLessonStep(lib, *o.lesson);
    if (ref.lesson < 0) return bad("--lesson: " + ref.error);
    ui::Lesson const& lesson = lib.lessons[std::size_t(ref.lesson)];
    ui::LessonStep const& step = lesson.steps[std::size_t(ref.step)];
    std::string error;
    Size2 size{lesson.width, lesson.height};
    if (o.given.count(cli::kSize.name)) {
        auto parsed = parseSize(o.size, &error);
        if (!parsed) return bad(error);
        size = *parsed;
    }
    std::vector<DebugView> views;
    for (auto const& name : o.views) {
        auto v = enumFromName<DebugView>(kDebugViewNames, name);
        if (!v) return bad("--view '" + name + "' is not a debug view");
        views.push_back(*v);
    }
    std::error_code ec;
    std::filesystem::create_directories(o.outDir, ec);
    if (ec) return bad("cannot create output directory " + o.outDir + ": " + ec.message());

    auto headless = createHeadlessRenderer(size.width, size.height, o.glLimit, &error);
    if (!headless) {
        std::fprintf(stderr, "gbuffer-lab render: %s\n", error.c_str());
        return 1;
    }
    Renderer& renderer = *headless->renderer;
    if (auto why = renderer.modeUnavailable(step.state.pipeline.mode)) return bad(*why);
    // The lesson's glTF scene (its lights and camera are the step's), or the default scene.
    SceneData scene;
    if (lesson.scenePath.empty()) {
        scene = makeDefaultScene({step.defaultSceneLights, step.defaultSceneGlass});
    } else {
        SceneRequest request;
        request.scenePath = lesson.scenePath;
        auto prepared = prepareScene(request, &error);
        if (!prepared) return bad("lesson " + lesson.id + ": " + error);
        scene = std::move(prepared->scene);
    }
    if (auto err = renderer.setScene(scene)) return bad(*err);
    LessonStepFrame const frame = renderLessonStep(renderer, step);
    FrameExport exported{step.state.camera, step.state.lights,     step.state.pipeline,
                         frame.stats,       scene.triangleCount(), views};
    if (auto err = exportFrame(renderer, exported, o.outDir)) return bad(*err);

    nlohmann::ordered_json claim = {{"lesson", lesson.id},
                                    {"step", ref.step + 1},
                                    {"title", step.text.title},
                                    {"pixel", {frame.pixel.x, frame.pixel.y}}};
    if (frame.claim) {
        claim["claim"] = std::string(ui::claimKindInfo(step.claim->kind).name);
        claim["holds"] = frame.claim->holds;
        claim["detail"] = frame.claim->detail;
    }
    std::string const claimPath = (std::filesystem::path(o.outDir) / "claim.json").string();
    std::ofstream f(claimPath);
    f << claim.dump(2) << "\n";
    if (!f) return bad("cannot write " + claimPath);
    std::printf("wrote %s (lesson %s step %d, %dx%d, %.2f GPU ms)%s%s\n", o.outDir.c_str(), lesson.id.c_str(),
                ref.step + 1, size.width, size.height, frame.stats.gpuFrameMs,
                frame.claim ? (frame.claim->holds ? "; claim holds: " : "; claim FAILS: ") : "",
                frame.claim ? frame.claim->detail.c_str() : "");
    return 0;
}

}  // namespace gbl
