// Named GLSL programs built from shaders/ (embedded copy), rebuilt when the sources change.
#pragma once

#include "gl/program.h"

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gbl {

struct ProgramDesc {
    std::string name;                                    // e.g. "geometry"
    std::vector<std::pair<GLenum, std::string>> stages;  // stage and file name in shaders/
    std::vector<std::string> defines;                    // inserted after #version as "#define X"
};

class ShaderLibrary {
public:
    // sourceDir: where hot reload looks for changed files; empty disables reloading.
    explicit ShaderLibrary(std::filesystem::path sourceDir);

    // Builds a program from the embedded sources. Returns false and fills *log on failure.
    bool add(ProgramDesc desc, std::string* log);
    bool has(std::string_view name) const;
    // The last program that built successfully. Asserts the name was added.
    gl::Program const& get(std::string_view name) const;

    // Rebuilds programs whose files changed on disk since the last look. A failed rebuild keeps
    // the previous program. Returns one message per program rebuilt ("reloaded X") or failed
    // (the whole info log with stage and file name).
    std::vector<std::string> reloadChanged();

    // Text of a shader file with #include lines expanded: from disk when reloading has seen a
    // change to it, otherwise the embedded copy. nullopt when unknown.
    std::optional<std::string> source(std::string const& file, std::string* error = nullptr) const;

private:
    struct Entry {
        ProgramDesc desc;
        gl::Program program;
    };
    std::optional<gl::Program> build(ProgramDesc const& desc, std::string* log) const;
    std::optional<std::string> rawSource(std::string const& file) const;

    std::filesystem::path sourceDir_;
    std::map<std::string, Entry, std::less<>> programs_;
    std::map<std::string, std::filesystem::file_time_type> seenTimes_;  // per file on disk
    std::map<std::string, std::string> diskOverrides_;                  // files read from disk
};

}  // namespace gbl
