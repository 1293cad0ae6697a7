// Shader sources, #include expansion and hot reload.
#include "gl/shader_library.h"

#include "core/tile_math.h"
#include "gl/embedded_shaders.h"
#include "gl/gl_api.h"
#include "gl/shader_bindings.h"

#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace gbl {

namespace fs = std::filesystem;

ShaderLibrary::ShaderLibrary(fs::path sourceDir) : sourceDir_(std::move(sourceDir)) {
    std::error_code ec;
    if (sourceDir_.empty() || !fs::is_directory(sourceDir_, ec)) {
        sourceDir_.clear();
        return;
    }
    for (auto const& s : embeddedShaders()) {
        auto const t = fs::last_write_time(sourceDir_ / s.name, ec);
        if (!ec) seenTimes_[s.name] = t;
    }
}

std::optional<std::string> ShaderLibrary::rawSource(std::string const& file) const {
    if (auto it = diskOverrides_.find(file); it != diskOverrides_.end()) return it->second;
    for (auto const& s : embeddedShaders())
        if (file == s.name) return std::string(s.source);
    return std::nullopt;
}

std::optional<std::string> ShaderLibrary::source(std::string const& file, std::string* error) const {
    auto raw = rawSource(file);
    if (!raw) {
        if (error) *error = "shader file " + file + " does not exist in shaders/";
        return std::nullopt;
    }
    // Expand `#include "name"` lines (one level is all the shaders use; nested works too).
    std::istringstream in(*raw);
    std::string out, line;
    while (std::getline(in, line)) {
        if (line.rfind("#include", 0) == 0) {
            auto const a = line.find('"'), b = line.rfind('"');
            if (a == std::string::npos || b <= a) {
                if (error) *error = file + ": malformed #include line: " + line;
                return std::nullopt;
            }
            auto inc = source(line.substr(a + 1, b - a - 1), error);
            if (!inc) return std::nullopt;
            out += *inc;
            out += '\n';
        } else {
            out += line;
            out += '\n';
        }
    }
    return out;
}

std::optional<std::string> ShaderLibrary::stageSource(ProgramId id, std::string const& file, std::string* error,
                                                      std::string const& variantDefine) const {
    auto text = source(file, error);
    if (!text) return std::nullopt;
    // Defines go right after the #version line, which must stay the first directive (the one-line
    // file header comment may come before it). GBL_PROGRAM_ID names the program in the
    // shader-checks report (shaders/shader_checks.glsl).
    auto const version = text->find("#version");
    auto const eol = text->find('\n', version == std::string::npos ? 0 : version);
    std::string defs = "#define GBL_PROGRAM_ID " + std::to_string(int(id)) + "\n";
    // The tile size of tiled and clustered lighting: one constant for C++ and every shader.
    defs += "#define GBL_TILE_SIZE " + std::to_string(kTileSize) + "\n";
    for (auto const& d : programInfo(id).desc.defines) defs += "#define " + d + "\n";
    if (!variantDefine.empty()) defs += "#define " + variantDefine + "\n";
    for (auto const& d : globalDefines_) defs += "#define " + d + "\n";
    // The light buffer's row width where it is a 2D texture (shaders/light_texels.glsl).
    defs += "#define GBL_LIGHT_TEXELS_PER_ROW " + std::to_string(gl::kLightTexelsPerRow) + "\n";
    std::size_t at = eol == std::string::npos ? text->size() : eol + 1;
    static constexpr std::string_view kCore = "#version 330 core";
    if (esProfile_ && version != std::string::npos && text->compare(version, kCore.size(), kCore) == 0) {
        // WebGL2: GLSL ES 3.00, whose #version must be the very first line (the file's header
        // comment moves below it). Precision statements are declarations, so they follow the
        // defines; ES gives the 3D, array, integer and shadow samplers no default precision.
        text->erase(version, eol + 1 - version);
        text->insert(0, "#version 300 es\n");
        at = std::string_view("#version 300 es\n").size();
        defs += "#define GBL_NO_BUFFER_TEXTURES\n";
        defs +=
            "precision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"
            "precision highp sampler3D;\nprecision highp samplerCube;\nprecision highp sampler2DArray;\n"
            "precision highp sampler2DShadow;\nprecision highp isampler2D;\nprecision highp usampler2D;\n";
    }
    text->insert(at, defs);
    return text;
}

std::optional<gl::Program> ShaderLibrary::build(ProgramId id, std::string* log,
                                                std::string const& variantDefine) const {
    ProgramDesc const& desc = programInfo(id).desc;
    std::vector<gl::ShaderStageSource> stages;
    for (auto const& [stage, file] : desc.stages) {
        std::string err;
        auto text = stageSource(id, file, &err, variantDefine);
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
    auto defines = variants_.find(globalDefines_);
    if (defines == variants_.end()) defines = variants_.emplace(globalDefines_, decltype(defines->second){}).first;
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
    if (defines == globalDefines_) return true;
    std::array<gl::Program, kProgramCount> previous = std::move(programs_);
    programs_ = {};
    if (auto kept = otherDefines_.find(defines); kept != otherDefines_.end()) {
        programs_ = std::move(kept->second);
        otherDefines_.erase(kept);
    }
    std::vector<std::string> left = std::exchange(globalDefines_, std::move(defines));
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
    if (sourceDir_.empty()) return messages;
    std::set<std::string> changed;
    std::error_code ec;
    for (auto& [file, seen] : seenTimes_) {
        auto const t = fs::last_write_time(sourceDir_ / file, ec);
        if (ec || t == seen) continue;
        seen = t;
        std::ifstream f(sourceDir_ / file, std::ios::binary);
        std::ostringstream ss;
        ss << f.rdbuf();
        diskOverrides_[file] = ss.str();
        changed.insert(file);
    }
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
