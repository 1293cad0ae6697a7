// Extension and version queries of the current context (gl_api.h).
#include "gl/gl_api.h"

#include <cstring>

namespace gbl::gl {

#ifdef __EMSCRIPTEN__
bool hasExtension(char const* name) {
    // Emscripten lists the WebGL extensions it enabled with a GL_ prefix; compare with and without.
    char const* bare = std::strncmp(name, "GL_", 3) == 0 ? name + 3 : name;
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        auto const* e = reinterpret_cast<char const*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
        if (!e) continue;
        char const* eBare = std::strncmp(e, "GL_", 3) == 0 ? e + 3 : e;
        if (std::strcmp(eBare, bare) == 0) return true;
    }
    return false;
}
int contextVersion() {
    return 30;  // WebGL2 is OpenGL ES 3.0
}
#else
bool hasExtension(char const* name) {
    return epoxy_has_gl_extension(name);
}
int contextVersion() {
    return epoxy_gl_version();
}
#endif

}  // namespace gbl::gl
