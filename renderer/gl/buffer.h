// A GL buffer object (vertices, indices, light data) owned by value.
#pragma once

#include "gl/gl_object.h"

#include <cstddef>
#include <string_view>

namespace gbl::gl {

struct BufferDeleter {
    static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};

class Buffer {
public:
    Buffer() = default;
    static Buffer create(GLenum target, std::size_t bytes, void const* data, GLenum usage, std::string_view label);

    GLuint id() const { return handle_.id(); }
    GLenum target() const { return target_; }
    std::size_t size() const { return size_; }
    explicit operator bool() const { return bool(handle_); }

    // Replaces the contents; grows (reallocates) when bytes exceeds the current size.
    void upload(std::size_t bytes, void const* data);

private:
    Handle<BufferDeleter> handle_;
    GLenum target_ = GL_ARRAY_BUFFER;
    GLenum usage_ = GL_STATIC_DRAW;
    std::size_t size_ = 0;
};

}  // namespace gbl::gl
