// The text of the renderer's shaders: the files of shaders/ (embedded copy, or from disk once hot
// reload has seen them change), #include lines expanded, and the text each program stage is compiled
// from. No GL call: ShaderLibrary builds programs from it, and the reference-compiler test
// (tests/shader_compile_test.cpp) checks the same text without a context.
#pragma once

#include "gl/program_id.h"

#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gbl {

class ShaderSources {
public:
    // sourceDir: where hot reload looks for changed files; empty disables reloading.
    explicit ShaderSources(std::filesystem::path sourceDir);

    // Text of a shader file with #include lines expanded: from disk when reloading has seen a
    // change to it, otherwise the embedded copy. nullopt when unknown.
    std::optional<std::string> source(std::string const& file, std::string* error = nullptr) const;
    // The text stage `file` of program `id` is compiled from: source(file) with the program's own
    // defines, `variantDefine`, the global ones and GBL_PROGRAM_ID inserted after #version.
    std::optional<std::string> stageSource(ProgramId id, std::string const& file, std::string* error = nullptr,
                                           std::string const& variantDefine = {}) const;

    // Defines every program gets after its own (the G-buffer layout's, core/gbuffer_layout.h).
    void setGlobalDefines(std::vector<std::string> defines) { globalDefines_ = std::move(defines); }
    std::vector<std::string> const& globalDefines() const { return globalDefines_; }
    // Whether stages are emitted as GLSL ES 3.00 for WebGL2 (gl::kGlslEs: on in the browser build):
    // `#version 330 core` becomes `#version 300 es` with precision statements and
    // GBL_NO_BUFFER_TEXTURES; compute stages (430) are left as they are, never built there. Settable
    // so the reference-compiler test checks the web's text natively too.
    void setEsProfile(bool on) { esProfile_ = on; }
    bool esProfile() const { return esProfile_; }

    // Reads the files whose modification time changed on disk since the last look; returns their names.
    std::set<std::string> readChanged();

private:
    std::optional<std::string> rawSource(std::string const& file) const;

    std::filesystem::path sourceDir_;
    std::vector<std::string> globalDefines_;
    bool esProfile_ = gl::kGlslEs;
    std::map<std::string, std::filesystem::file_time_type> seenTimes_;  // per file on disk
    std::map<std::string, std::string> diskOverrides_;                  // files read from disk
};

}  // namespace gbl
