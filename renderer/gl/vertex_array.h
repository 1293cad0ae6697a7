// A vertex array object owned by value.
#pragma once

#include "gl/gl_object.h"

#include <string_view>

namespace gbl::gl {

struct VertexArrayDeleter {
    static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};

class VertexArray {
public:
    VertexArray() = default;
    static VertexArray create(std::string_view label) {
        VertexArray v;
        GLuint id = 0;
        glGenVertexArrays(1, &id);
        v.handle_ = Handle<VertexArrayDeleter>(id);
        // Labels need the object to exist, which for VAOs means bound once.
        glBindVertexArray(id);
        glBindVertexArray(0);
        setLabel(GL_VERTEX_ARRAY, id, label);
        return v;
    }
    GLuint id() const { return handle_.id(); }
    explicit operator bool() const { return bool(handle_); }

private:
    Handle<VertexArrayDeleter> handle_;
};

}  // namespace gbl::gl
