// Texture creation with storage that never changes size (targets are recreated on resize).
#include "gl/texture.h"

#include <algorithm>

namespace gbl::gl {

namespace {
// Format/type pairs for glTexImage2D; the data pointer is null so they only need to be valid.
void formatAndType(GLenum internalFormat, GLenum& format, GLenum& type) {
    switch (internalFormat) {
        case GL_DEPTH32F_STENCIL8:
            format = GL_DEPTH_STENCIL;
            type = GL_FLOAT_32_UNSIGNED_INT_24_8_REV;
            return;
        case GL_DEPTH24_STENCIL8:
            format = GL_DEPTH_STENCIL;
            type = GL_UNSIGNED_INT_24_8;
            return;
        case GL_DEPTH_COMPONENT32F:
            format = GL_DEPTH_COMPONENT;
            type = GL_FLOAT;
            return;
        case GL_R8:
        case GL_R16F:
        case GL_R32F:
            format = GL_RED;
            type = GL_FLOAT;
            return;
        case GL_R32UI:
            format = GL_RED_INTEGER;
            type = GL_UNSIGNED_INT;
            return;
        case GL_R32I:
            format = GL_RED_INTEGER;
            type = GL_INT;
            return;
        case GL_RG16F:
        case GL_RG32F:
            format = GL_RG;
            type = GL_FLOAT;
            return;
        case GL_RGB8:
        case GL_SRGB8:
        case GL_RGB16F:
            format = GL_RGB;
            type = GL_FLOAT;
            return;
        default:
            format = GL_RGBA;
            type = GL_FLOAT;
            return;
    }
}
}  // namespace

Texture Texture::create2D(GLenum internalFormat, int width, int height, std::string_view label, int levels) {
    Texture t;
    GLuint id = 0;
    glGenTextures(1, &id);
    t.handle_ = Handle<TextureDeleter>(id);
    t.target_ = GL_TEXTURE_2D;
    t.internalFormat_ = internalFormat;
    t.width_ = width;
    t.height_ = height;
    glBindTexture(GL_TEXTURE_2D, id);
    GLenum format = 0, type = 0;
    formatAndType(internalFormat, format, type);
    // glTexStorage2D is GL 4.2; glTexImage2D per level keeps the 3.3 floor. WebGL2 (ES 3.0) has
    // glTexStorage2D and accepts only exact format/type pairs in glTexImage2D, so it takes that.
    int w = std::max(width, 1), h = std::max(height, 1);
    if (kWebGL2) glTexStorage2D(GL_TEXTURE_2D, levels, internalFormat, w, h);
    for (int level = 0; level < levels && !kWebGL2; ++level) {
        glTexImage2D(GL_TEXTURE_2D, level, GLint(internalFormat), w, h, 0, format, type, nullptr);
        w = std::max(w / 2, 1);
        h = std::max(h / 2, 1);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels - 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, levels > 1 ? GL_LINEAR : GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    setLabel(GL_TEXTURE, id, label);
    return t;
}

Texture Texture::create2DMultisample(GLenum internalFormat, int width, int height, int samples,
                                     std::string_view label) {
    Texture t;
    GLuint id = 0;
    glGenTextures(1, &id);
    t.handle_ = Handle<TextureDeleter>(id);
    t.target_ = GL_TEXTURE_2D_MULTISAMPLE;
    t.internalFormat_ = internalFormat;
    t.width_ = width;
    t.height_ = height;
    t.samples_ = samples;
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, id);
    glTexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples, internalFormat, std::max(width, 1), std::max(height, 1),
                            GL_TRUE);
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
    setLabel(GL_TEXTURE, id, label);
    return t;
}

Texture Texture::createBuffer(GLenum internalFormat, GLuint buffer, std::string_view label) {
    Texture t;
    GLuint id = 0;
    glGenTextures(1, &id);
    t.handle_ = Handle<TextureDeleter>(id);
    t.target_ = GL_TEXTURE_BUFFER;
    t.internalFormat_ = internalFormat;
    glBindTexture(GL_TEXTURE_BUFFER, id);
    glTexBuffer(GL_TEXTURE_BUFFER, internalFormat, buffer);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    setLabel(GL_TEXTURE, id, label);
    return t;
}

void Texture::setFilter(GLenum minFilter, GLenum magFilter) const {
    glBindTexture(target_, id());
    glTexParameteri(target_, GL_TEXTURE_MIN_FILTER, GLint(minFilter));
    glTexParameteri(target_, GL_TEXTURE_MAG_FILTER, GLint(magFilter));
    glBindTexture(target_, 0);
}

void Texture::setWrap(GLenum wrap) const {
    glBindTexture(target_, id());
    glTexParameteri(target_, GL_TEXTURE_WRAP_S, GLint(wrap));
    glTexParameteri(target_, GL_TEXTURE_WRAP_T, GLint(wrap));
    glBindTexture(target_, 0);
}

}  // namespace gbl::gl
