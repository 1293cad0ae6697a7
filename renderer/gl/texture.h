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
    // Multisampled 2D storage (GL_TEXTURE_2D_MULTISAMPLE, core since GL 3.2): `samples` per texel,
    // at the same positions in every texel. Read with texelFetch(sampler2DMS, p, sample).
    static Texture create2DMultisample(GLenum internalFormat, int width, int height, int samples,
                                       std::string_view label);
    // A buffer texture viewing `buffer` (a GL buffer name) as `internalFormat` texels.
    static Texture createBuffer(GLenum internalFormat, GLuint buffer, std::string_view label);

    GLuint id() const { return handle_.id(); }
    GLenum target() const { return target_; }
    GLenum internalFormat() const { return internalFormat_; }
    int width() const { return width_; }
    int height() const { return height_; }
    int samples() const { return samples_; }  // 1 for a single-sampled texture
    explicit operator bool() const { return bool(handle_); }

    void setFilter(GLenum minFilter, GLenum magFilter) const;
    void setWrap(GLenum wrap) const;

private:
    Handle<TextureDeleter> handle_;
    GLenum target_ = GL_TEXTURE_2D;
    GLenum internalFormat_ = 0;
    int width_ = 0;
    int height_ = 0;
    int samples_ = 1;
};

}  // namespace gbl::gl
