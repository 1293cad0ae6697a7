// A GL query object (timer or pipeline statistics) owned by value.
#pragma once

#include "gl/gl_object.h"

#include <string_view>

namespace gbl::gl {

struct QueryDeleter {
    static void destroy(GLuint id) { glDeleteQueries(1, &id); }
};

class Query {
public:
    Query() = default;
    static Query create(GLenum target, std::string_view label) {
        Query q;
        GLuint id = 0;
        glGenQueries(1, &id);
        q.handle_ = Handle<QueryDeleter>(id);
        q.target_ = target;
        // The label is set after the first begin/end: a query object exists only once used.
        q.label_ = label;
        return q;
    }
    GLuint id() const { return handle_.id(); }
    GLenum target() const { return target_; }
    explicit operator bool() const { return bool(handle_); }
    void begin() const { glBeginQuery(target_, id()); }
    void end() const { glEndQuery(target_); }
    bool resultAvailable() const {
        GLint ready = 0;
        glGetQueryObjectiv(id(), GL_QUERY_RESULT_AVAILABLE, &ready);
        return ready != 0;
    }
    GLuint64 result() const {
        GLuint64 v = 0;
        glGetQueryObjectui64v(id(), GL_QUERY_RESULT, &v);
        return v;
    }

private:
    Handle<QueryDeleter> handle_;
    GLenum target_ = GL_TIME_ELAPSED;
    std::string_view label_;
};

}  // namespace gbl::gl
