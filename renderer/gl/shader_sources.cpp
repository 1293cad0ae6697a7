// Shader sources: the embedded files or their changed copies on disk, #include expansion, stage text.
#include "gl/shader_sources.h"

#include "core/tile_math.h"
#include "gl/embedded_shaders.h"

#include <fstream>
#include <sstream>
#include <string_view>
#include <utility>

namespace gbl {

namespace fs = std::filesystem;

ShaderSources::ShaderSources(fs::path sourceDir) : sourceDir_(std::move(sourceDir)) {
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

std::optional<std::string> ShaderSources::rawSource(std::string const& file) const {
    if (auto it = diskOverrides_.find(file); it != diskOverrides_.end()) return it->second;
    for (auto const& s : embeddedShaders())
        if (file == s.name) return std::string(s.source);
    return std::nullopt;
}

std::optional<std::string> ShaderSources::source(std::string const& file, std::string* error) const {
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

std::optional<std::string> ShaderSources::stageSource(ProgramId id, std::string const& file, std::string* error,
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

std::set<std::string> ShaderSources::readChanged() {
    std::set<std::string> changed;
    if (sourceDir_.empty()) return changed;
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
    return changed;
}

}  // namespace gbl
