// Programs built from the shader sources (gl/shader_sources.h), per set of defines, and hot reload.
#include "gl/shader_library.h"

#include "gl/gl_api.h"
#include "gl/shader_bindings.h"

#include <set>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace gbl {

namespace fs = std::filesystem;

ShaderLibrary::ShaderLibrary(fs::path sourceDir) : sources_(std::move(sourceDir)) {}

std::optional<gl::Program> ShaderLibrary::build(ProgramId id, std::string* log,
                                                std::string const& variantDefine) const {
    ProgramDesc const& desc = programInfo(id).desc;
    std::vector<gl::ShaderStageSource> stages;
    for (auto const& [stage, file] : desc.stages) {
        std::string err;
        auto text = sources_.stageSource(id, file, &err, variantDefine);
        if (!text) {
            if (log) *log = "program " + desc.name + ": " + err;
            return std::nullopt;
        }
        stages.push_back({stage, file, std::move(*text)});
    }
    return gl::Program::build(stages, desc.name, log);
}

namespace {
// Points every sampler the program declares at its unit from shaders/bindings.glsl, once after
// linking, so no pass sets a unit by hand.
void bindSamplerSlots(gl::Program const& program) {
    program.use();
    for (slot::SamplerSlot const& s : slot::kSamplerSlots) program.set(s.uniform, s.unit);
    glUseProgram(0);
}
}  // namespace

bool ShaderLibrary::add(ProgramId id, std::string* log) {
    std::string buildLog;
    auto program = build(id, &buildLog);
    if (log) *log = buildLog;
    if (!program) {
        failures_[std::size_t(id)] = buildLog.empty() ? "unknown error" : buildLog;
        return false;
    }
    bindSamplerSlots(*program);
    programs_[std::size_t(id)] = std::move(*program);
    ++builds_;
    failures_[std::size_t(id)].clear();
    return true;
}

gl::Program const& ShaderLibrary::variant(ProgramId id, std::string const& define) {
    auto defines = variants_.find(sources_.globalDefines());
    if (defines == variants_.end())
        defines = variants_.emplace(sources_.globalDefines(), decltype(defines->second){}).first;
    auto found = defines->second.find(std::make_pair(id, define));
    if (found == defines->second.end()) {
        std::string log;
        auto program = build(id, &log, define);
        if (program) {
            bindSamplerSlots(*program);
            ++builds_;
        }
        found =
            defines->second.emplace(std::make_pair(id, define), program ? std::move(*program) : gl::Program{}).first;
    }
    return found->second ? found->second : get(id);
}

bool ShaderLibrary::setGlobalDefines(std::vector<std::string> defines, std::string* log) {
    if (defines == sources_.globalDefines()) return true;
    std::array<gl::Program, kProgramCount> previous = std::move(programs_);
    programs_ = {};
    if (auto kept = otherDefines_.find(defines); kept != otherDefines_.end()) {
        programs_ = std::move(kept->second);
        otherDefines_.erase(kept);
    }
    std::vector<std::string> left = sources_.globalDefines();
    sources_.setGlobalDefines(std::move(defines));
    bool ok = true;
    for (ProgramInfo const& info : programTable()) {
        std::size_t const i = std::size_t(info.id);
        // Never built under the old defines: built with the new ones on first use; kept from an
        // earlier switch: nothing to build.
        if (!previous[i] || programs_[i]) continue;
        std::string buildLog;
        if (add(info.id, &buildLog)) continue;
        programs_[i] = std::move(previous[i]);  // the failed one keeps its previous build
        if (ok && log) *log = buildLog;
        ok = false;
    }
    otherDefines_[std::move(left)] = std::move(previous);
    return ok;
}

std::vector<std::string> ShaderLibrary::reloadChanged() {
    std::vector<std::string> messages;
    std::set<std::string> const changed = sources_.readChanged();
    if (changed.empty()) return messages;
    // Programs are deleted below: the one still in use would live on, flagged, until the next
    // glUseProgram, and a caller that saved and restores it (ImGui's renderer does) would then
    // name a deleted program.
    glUseProgram(0);
    otherDefines_.clear();  // built from the old sources
    variants_.clear();
    for (ProgramInfo const& info : programTable()) {
        gl::Program& current = programs_[std::size_t(info.id)];
        if (!current) continue;  // never built: its group builds it on first use
        std::string const& name = info.desc.name;
        // A program depends on its stage files and on everything they include; rebuilding
        // every program when any included file changed is simpler and still cheap.
        bool affected = false;
        for (auto const& [stage, file] : info.desc.stages) affected |= changed.count(file) > 0;
        for (auto const& f : changed) affected |= f.ends_with(".glsl");
        if (!affected) continue;
        std::string log;
        if (auto program = build(info.id, &log)) {
            bindSamplerSlots(*program);
            current = std::move(*program);
            messages.push_back("reloaded shader program " + name);
        } else {
            messages.push_back("shader program " + name + " failed to rebuild; keeping the last good one.\n" + log);
        }
    }
    return messages;
}

}  // namespace gbl
