// Shader compilation and linking with complete error logs.
#include "gl/program.h"

namespace gbl::gl {

namespace {
char const* stageName(GLenum stage) {
    switch (stage) {
        case GL_VERTEX_SHADER:
            return "vertex";
        case GL_FRAGMENT_SHADER:
            return "fragment";
        case GL_COMPUTE_SHADER:
            return "compute";
        default:
            return "shader";
    }
}

std::string infoLog(GLuint object, bool isProgram) {
    GLint length = 0;
    if (isProgram)
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string text(std::size_t(length > 0 ? length : 0), '\0');
    if (length > 0) {
        if (isProgram)
            glGetProgramInfoLog(object, length, nullptr, text.data());
        else
            glGetShaderInfoLog(object, length, nullptr, text.data());
    }
    while (!text.empty() && (text.back() == '\0' || text.back() == '\n')) text.pop_back();
    return text;
}
}  // namespace

std::optional<Program> Program::build(std::vector<ShaderStageSource> const& stages, std::string_view label,
                                      std::string* log) {
    std::vector<GLuint> shaders;
    bool ok = true;
    std::string messages;
    for (auto const& s : stages) {
        GLuint const sh = glCreateShader(s.stage);
        char const* src = s.source.c_str();
        glShaderSource(sh, 1, &src, nullptr);
        glCompileShader(sh);
        GLint status = 0;
        glGetShaderiv(sh, GL_COMPILE_STATUS, &status);
        if (!status) {
            ok = false;
            messages += std::string("failed to compile ") + stageName(s.stage) + " shader " + s.fileName + ":\n" +
                        infoLog(sh, false) + "\n";
        }
        shaders.push_back(sh);
    }
    GLuint const prog = glCreateProgram();
    if (ok) {
        for (GLuint sh : shaders) glAttachShader(prog, sh);
        glLinkProgram(prog);
        GLint status = 0;
        glGetProgramiv(prog, GL_LINK_STATUS, &status);
        if (!status) {
            ok = false;
            messages += "failed to link program " + std::string(label) + ":\n" + infoLog(prog, true) + "\n";
        }
        for (GLuint sh : shaders) glDetachShader(prog, sh);
    }
    for (GLuint sh : shaders) glDeleteShader(sh);
    if (!ok) {
        glDeleteProgram(prog);
        if (log) *log = messages;
        return std::nullopt;
    }
    Program p;
    p.handle_ = Handle<ProgramDeleter>(prog);
    setLabel(GL_PROGRAM, prog, label);
    return p;
}

GLint Program::uniform(std::string_view name) const {
    std::string key(name);
    auto it = uniforms_.find(key);
    if (it != uniforms_.end()) return it->second;
    GLint const loc = glGetUniformLocation(id(), key.c_str());
    uniforms_.emplace(std::move(key), loc);
    return loc;
}

}  // namespace gbl::gl
