// The lesson folder: every lesson file of a directory, and "ID:STEP" references into it.
#include "session/lesson_file.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace gbl::ui {

namespace fs = std::filesystem;

std::string defaultLessonDir() {
    if (char const* env = std::getenv("GBL_LESSONS_DIR"); env && *env) return env;
    return GBL_LESSONS_DIR;
}

std::string sharedModelsDir() {
    if (char const* env = std::getenv("GBL_SHARED_GLTF_DIR"); env && *env) return env;
    return GBL_SHARED_MODELS_DIR;
}

LessonLibrary loadLessonDir(std::string const& dir) {
    LessonLibrary lib;
    std::error_code ec;
    std::vector<std::string> files;
    for (auto const& e : fs::directory_iterator(dir, ec))
        if (e.path().extension() == ".json") files.push_back(e.path().string());
    if (ec) {
        lib.errors.push_back("cannot list lessons in " + dir + ": " + ec.message());
        return lib;
    }
    std::sort(files.begin(), files.end());
    for (auto const& f : files) {
        LessonLoad load = loadLesson(f);
        if (!load.lesson) {
            lib.errors.push_back(load.error);
            continue;
        }
        bool const dup = std::any_of(lib.lessons.begin(), lib.lessons.end(),
                                     [&](Lesson const& l) { return l.id == load.lesson->id; });
        if (dup)
            lib.errors.push_back(f + ": id \"" + load.lesson->id + "\" is already used by another lesson");
        else
            lib.lessons.push_back(std::move(*load.lesson));
    }
    return lib;
}

LessonRef findLessonStep(LessonLibrary const& library, std::string_view ref) {
    LessonRef out;
    std::string_view id = ref;
    std::string_view step;
    if (auto colon = ref.find(':'); colon != std::string_view::npos) {
        id = ref.substr(0, colon);
        step = ref.substr(colon + 1);
    }
    for (std::size_t i = 0; i < library.lessons.size(); ++i)
        if (library.lessons[i].id == id) out.lesson = int(i);
    if (out.lesson < 0) {
        std::string ids;
        for (auto const& l : library.lessons) ids += (ids.empty() ? "" : ", ") + l.id;
        out.error = "no lesson has the id \"" + std::string(id) + "\" (lessons: " + ids + ")";
        return out;
    }
    int const count = int(library.lessons[std::size_t(out.lesson)].steps.size());
    if (!step.empty()) {
        int n = 0;
        bool digits = step.find_first_not_of("0123456789") == std::string_view::npos && step.size() < 6;
        if (digits) n = std::stoi(std::string(step));
        if (!digits || n < 1 || n > count) {
            out.error = "lesson " + std::string(id) + " has steps 1 to " + std::to_string(count) + ", not \"" +
                        std::string(step) + "\"";
            out.lesson = -1;
            return out;
        }
        out.step = n - 1;
    }
    return out;
}

}  // namespace gbl::ui
