// GL debug output and error counting.
#include "gl/debug.h"

#include "gl/gl_api.h"

#include <atomic>
#include <cstdio>

namespace gbl {

namespace {
std::atomic<std::uint64_t> gErrors{0};
std::atomic<bool> gCallbackActive{false};

void GLAPIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei, GLchar const* message,
                               void const*) {
    // Compile errors arrive here too; the shader library reports them with the whole log, and
    // a bad shader edit is user input, not a GL error.
    if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
    if (type == GL_DEBUG_TYPE_ERROR) {
        ++gErrors;
        std::fprintf(stderr, "GL error (id %u): %s\n", id, message);
    } else if (severity == GL_DEBUG_SEVERITY_HIGH) {
        std::fprintf(stderr, "GL warning (id %u): %s\n", id, message);
    }
}
}  // namespace

void installGlDebug(GlCaps const& caps) {
    if (!caps.khrDebug) return;
    glEnable(GL_DEBUG_OUTPUT);
    // Synchronous output ties each message to the call that caused it (worth the cost here).
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, nullptr);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
    gCallbackActive = true;
}

std::uint64_t glErrorCount() {
    for (int i = 0; i < 64; ++i) {
        GLenum const e = glGetError();
        if (e == GL_NO_ERROR) break;
        // With the callback active the flag repeats an error the callback already counted.
        if (gCallbackActive) continue;
        ++gErrors;
        std::fprintf(stderr, "GL error 0x%04x\n", e);
    }
    return gErrors.load();
}

}  // namespace gbl
