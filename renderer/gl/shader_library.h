// The renderer's GLSL programs (gl/program_id.h) built from shaders/ (embedded copy), rebuilt
// when the sources change.
#pragma once

#include "gl/program.h"
#include "gl/program_id.h"
#include "gl/shader_sources.h"

#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gbl {

class ShaderLibrary {
public:
    // sourceDir: where hot reload looks for changed files; empty disables reloading.
    explicit ShaderLibrary(std::filesystem::path sourceDir);

    // Builds the program from its sources and points its samplers at the units of
    // shaders/bindings.glsl. Returns false and fills *log on failure; the log is also kept
    // (failureLog) until a later build succeeds.
    bool add(ProgramId id, std::string* log);
    // Programs compiled and linked so far (successful builds), for tests of what a switch costs.
    std::size_t buildCount() const { return builds_; }
    bool has(ProgramId id) const { return bool(programs_[std::size_t(id)]); }
    // The last program of `id` that built successfully; an empty program (which draws nothing
    // and raises a GL error the tests catch) when it never built. Callers build optional
    // programs first and check has().
    gl::Program const& get(ProgramId id) const { return programs_[std::size_t(id)]; }
    // The compiler's log of the last failed build of `id`; empty when it built or was never tried.
    std::string const& failureLog(ProgramId id) const { return failures_[std::size_t(id)]; }

    // Program `id` built with one define more (e.g. "VIEW_ONLY 3"), made on first use and kept
    // per set of global defines: code that a uniform would select at every pixel is selected by
    // the compiler instead. get(id) when the variant fails to build (e.g. a file broken by hot
    // reload, which reloadChanged reports): a variant that failed is tried again only after the
    // next change on disk.
    gl::Program const& variant(ProgramId id, std::string const& define);
    // Rebuilds programs whose files changed on disk since the last look. A failed rebuild keeps
    // the previous program. Returns one message per program rebuilt ("reloaded X") or failed
    // (the whole info log with stage and file name).
    std::vector<std::string> reloadChanged();

    // Defines every program gets after its own (the G-buffer layout's, core/gbuffer_layout.h).
    // Switches every program built so far to the new defines; returns false and fills *log with
    // the first failure (that program keeps its previous build). The programs of the defines left
    // are kept, so switching back costs no build (the A/B split renders two layouts a frame).
    bool setGlobalDefines(std::vector<std::string> defines, std::string* log);

    // The shader text (gl/shader_sources.h): files with #include expanded, each stage's text.
    std::optional<std::string> source(std::string const& file, std::string* error = nullptr) const {
        return sources_.source(file, error);
    }
    std::optional<std::string> stageSource(ProgramId id, std::string const& file, std::string* error = nullptr,
                                           std::string const& variantDefine = {}) const {
        return sources_.stageSource(id, file, error, variantDefine);
    }
    std::vector<std::string> const& globalDefines() const { return sources_.globalDefines(); }
    void setEsProfile(bool on) { sources_.setEsProfile(on); }
    bool esProfile() const { return sources_.esProfile(); }

private:
    std::optional<gl::Program> build(ProgramId id, std::string* log, std::string const& variantDefine = {}) const;

    ShaderSources sources_;
    std::array<gl::Program, kProgramCount> programs_;
    std::size_t builds_ = 0;
    // Programs built for other global defines; dropped when a shader file changes on disk.
    std::map<std::vector<std::string>, std::array<gl::Program, kProgramCount>> otherDefines_;
    std::array<std::string, kProgramCount> failures_;
    // variant(): by global defines, then program and define (looked up without copying the
    // defines, as each frame does); an empty program marks a failed build.
    std::map<std::vector<std::string>, std::map<std::pair<ProgramId, std::string>, gl::Program>> variants_;
};

}  // namespace gbl
