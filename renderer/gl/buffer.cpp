// Buffer creation and re-upload.
#include "gl/buffer.h"

namespace gbl::gl {

Buffer Buffer::create(GLenum target, std::size_t bytes, void const* data, GLenum usage, std::string_view label) {
    Buffer b;
    GLuint id = 0;
    glGenBuffers(1, &id);
    b.handle_ = Handle<BufferDeleter>(id);
    b.target_ = target;
    b.usage_ = usage;
    b.size_ = bytes;
    glBindBuffer(target, id);
    glBufferData(target, GLsizeiptr(bytes), data, usage);
    glBindBuffer(target, 0);
    setLabel(GL_BUFFER, id, label);
    return b;
}

void Buffer::upload(std::size_t bytes, void const* data) {
    glBindBuffer(target_, id());
    if (bytes > size_) {
        glBufferData(target_, GLsizeiptr(bytes), data, usage_);
        size_ = bytes;
    } else if (bytes > 0) {
        glBufferSubData(target_, 0, GLsizeiptr(bytes), data);
    }
    glBindBuffer(target_, 0);
}

}  // namespace gbl::gl
