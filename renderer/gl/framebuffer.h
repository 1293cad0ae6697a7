// A framebuffer object owned by value, with completeness reported by status name.
#pragma once

#include "gl/gl_object.h"
#include "gl/texture.h"

#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace gbl::gl {

struct FramebufferDeleter {
    static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};

class Framebuffer {
public:
    Framebuffer() = default;
    // Attaches colour textures to GL_COLOR_ATTACHMENT0.. in order and an optional depth(-stencil)
    // texture, enables those draw buffers, and checks completeness.
    static Framebuffer create(std::initializer_list<Texture const*> colors, Texture const* depth,
                              std::string_view label);
    static Framebuffer create(std::span<Texture const* const> colors, Texture const* depth, std::string_view label);

    GLuint id() const { return handle_.id(); }
    explicit operator bool() const { return bool(handle_); }
    // Empty when complete, otherwise "GL_FRAMEBUFFER_INCOMPLETE_..." with the label.
    std::optional<std::string> const& error() const { return error_; }

private:
    Handle<FramebufferDeleter> handle_;
    std::optional<std::string> error_;
};

// Name of a glCheckFramebufferStatus value, e.g. "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT".
std::string_view framebufferStatusName(GLenum status);

}  // namespace gbl::gl
