// Framebuffer assembly and completeness checks.
#include "gl/framebuffer.h"

#include <vector>

namespace gbl::gl {

std::string_view framebufferStatusName(GLenum status) {
    switch (status) {
        case GL_FRAMEBUFFER_COMPLETE:
            return "GL_FRAMEBUFFER_COMPLETE";
        case GL_FRAMEBUFFER_UNDEFINED:
            return "GL_FRAMEBUFFER_UNDEFINED";
        case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
            return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
            return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER:
            return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
        case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER:
            return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
        case GL_FRAMEBUFFER_UNSUPPORTED:
            return "GL_FRAMEBUFFER_UNSUPPORTED";
        case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE:
            return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
        case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS:
            return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
        default:
            return "unknown framebuffer status";
    }
}

Framebuffer Framebuffer::create(std::initializer_list<Texture const*> colors, Texture const* depth,
                                std::string_view label) {
    return create(std::span<Texture const* const>(colors.begin(), colors.size()), depth, label);
}

Framebuffer Framebuffer::create(std::span<Texture const* const> colors, Texture const* depth, std::string_view label) {
    Framebuffer fb;
    GLuint id = 0;
    glGenFramebuffers(1, &id);
    fb.handle_ = Handle<FramebufferDeleter>(id);
    glBindFramebuffer(GL_FRAMEBUFFER, id);
    std::vector<GLenum> drawBuffers;
    GLenum slot = GL_COLOR_ATTACHMENT0;
    for (Texture const* c : colors) {
        glFramebufferTexture2D(GL_FRAMEBUFFER, slot, c->target(), c->id(), 0);
        drawBuffers.push_back(slot++);
    }
    if (depth) {
        bool const hasStencil =
            depth->internalFormat() == GL_DEPTH32F_STENCIL8 || depth->internalFormat() == GL_DEPTH24_STENCIL8;
        glFramebufferTexture2D(GL_FRAMEBUFFER, hasStencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                               depth->target(), depth->id(), 0);
    }
    if (drawBuffers.empty()) {
        glDrawBuffer(GL_NONE);
        glReadBuffer(GL_NONE);
    } else {
        glDrawBuffers(GLsizei(drawBuffers.size()), drawBuffers.data());
    }
    GLenum const status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        fb.error_ = std::string("framebuffer '") + std::string(label) +
                    "' is incomplete: " + std::string(framebufferStatusName(status));
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    setLabel(GL_FRAMEBUFFER, id, label);
    return fb;
}

}  // namespace gbl::gl
