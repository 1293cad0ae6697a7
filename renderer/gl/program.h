// A linked GLSL program owned by value, with cached uniform locations.
#pragma once

#include "gl/gl_object.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace gbl::gl {

struct ProgramDeleter {
    static void destroy(GLuint id) { glDeleteProgram(id); }
};

struct ShaderStageSource {
    GLenum stage;          // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER
    std::string fileName;  // for error messages
    std::string source;
};

class Program {
public:
    Program() = default;
    // Compiles and links; on failure returns nullopt and puts every stage's info log, with
    // the stage and file name, into *log.
    static std::optional<Program> build(std::vector<ShaderStageSource> const& stages, std::string_view label,
                                        std::string* log);

    GLuint id() const { return handle_.id(); }
    explicit operator bool() const { return bool(handle_); }
    void use() const { glUseProgram(id()); }

    // -1 when the uniform does not exist (optimised out); setting -1 is a GL no-op.
    GLint uniform(std::string_view name) const;
    void set(std::string_view name, int v) const { glUniform1i(uniform(name), v); }
    void set(std::string_view name, float v) const { glUniform1f(uniform(name), v); }
    void set(std::string_view name, glm::vec2 v) const { glUniform2f(uniform(name), v.x, v.y); }
    void set(std::string_view name, glm::ivec2 v) const { glUniform2i(uniform(name), v.x, v.y); }
    void set(std::string_view name, glm::vec3 v) const { glUniform3f(uniform(name), v.x, v.y, v.z); }
    void set(std::string_view name, glm::vec4 v) const { glUniform4f(uniform(name), v.x, v.y, v.z, v.w); }
    void set(std::string_view name, glm::mat3 const& m) const {
        glUniformMatrix3fv(uniform(name), 1, GL_FALSE, &m[0][0]);
    }
    void set(std::string_view name, glm::mat4 const& m) const {
        glUniformMatrix4fv(uniform(name), 1, GL_FALSE, &m[0][0]);
    }

private:
    Handle<ProgramDeleter> handle_;
    mutable std::unordered_map<std::string, GLint> uniforms_;
};

}  // namespace gbl::gl
