// Move-only ownership of one GL object name; the per-type headers build on this.
#pragma once

#include "gl/gl_api.h"

#include <string_view>
#include <utility>

namespace gbl::gl {

// Number of GL objects created through these wrappers and not yet deleted (soak tests watch it).
int liveObjectCount();

namespace detail {
void countCreated();
void countDeleted();
}  // namespace detail

// Gives the object a name that debuggers and KHR_debug messages show; a no-op without KHR_debug.
void setLabel(GLenum identifier, GLuint id, std::string_view label);

// Deleter is a type with `static void destroy(GLuint)`.
template <class Deleter>
class Handle {
public:
    Handle() = default;
    explicit Handle(GLuint id) : id_(id) {
        if (id_) detail::countCreated();
    }
    ~Handle() { reset(); }
    Handle(Handle const&) = delete;
    Handle& operator=(Handle const&) = delete;
    Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_) {
            Deleter::destroy(id_);
            detail::countDeleted();
            id_ = 0;
        }
    }

private:
    GLuint id_ = 0;
};

}  // namespace gbl::gl
