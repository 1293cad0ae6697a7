// A 2D texture (or texture buffer) owned by value.
#pragma once

#include "gl/gl_object.h"

#include <string_view>

namespace gbl::gl {

struct TextureDeleter {
    static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};

class Texture {
public:
    Texture() = default;
    // Immutable-size 2D storage; levels > 1 allocates a mip chain.
    static Texture create2D(GLenum internalFormat, int width, int height, std::string_view label, int levels = 1);
    // A buffer texture viewing `buffer` (a GL buffer name) as `internalFormat` texels.
    static Texture createBuffer(GLenum internalFormat, GLuint buffer, std::string_view label);

    GLuint id() const { return handle_.id(); }
    GLenum target() const { return target_; }
    GLenum internalFormat() const { return internalFormat_; }
    int width() const { return width_; }
    int height() const { return height_; }
    explicit operator bool() const { return bool(handle_); }

    void setFilter(GLenum minFilter, GLenum magFilter) const;
    void setWrap(GLenum wrap) const;

private:
    Handle<TextureDeleter> handle_;
    GLenum target_ = GL_TEXTURE_2D;
    GLenum internalFormat_ = 0;
    int width_ = 0;
    int height_ = 0;
};

}  // namespace gbl::gl
