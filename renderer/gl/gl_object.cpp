// Live-object counting and debug labels for the GL wrappers.
#include "gl/gl_object.h"

#include <atomic>

namespace gbl::gl {

namespace {
std::atomic<int> gLive{0};
bool labelsSupported() {
    // Queried per call: cheap, and correct if several contexts of different versions exist.
    return contextVersion() >= 43 || hasExtension("GL_KHR_debug");
}
}  // namespace

int liveObjectCount() {
    return gLive.load();
}

namespace detail {
void countCreated() {
    ++gLive;
}
void countDeleted() {
    --gLive;
}
}  // namespace detail

void setLabel(GLenum identifier, GLuint id, std::string_view label) {
    if (id == 0 || label.empty() || !labelsSupported()) return;
    glObjectLabel(identifier, id, GLsizei(label.size()), label.data());
}

}  // namespace gbl::gl
