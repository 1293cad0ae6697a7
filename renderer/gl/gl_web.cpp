// The desktop GL entry points WebGL2 lacks (gl_web_missing.h), for the web build only. Those with a
// WebGL2 equivalent forward to it; the rest do nothing and say so once on the console, since each
// caller is behind a GlCaps flag that WebGL2 reports false.
#ifdef __EMSCRIPTEN__
#include "gl/gl_api.h"

#include <cstdio>
#include <set>
#include <string>

namespace {
void missing(char const* name) {
    static std::set<std::string> said;
    if (said.insert(name).second) std::printf("gbuffer-lab (web): %s is not in WebGL2, ignored\n", name);
}
}  // namespace

extern "C" {
void glDispatchCompute(GLuint, GLuint, GLuint) {
    missing("glDispatchCompute");
}
void glMemoryBarrier(GLbitfield) {
    missing("glMemoryBarrier");
}
void glBindImageTexture(GLuint, GLuint, GLint, GLboolean, GLint, GLenum, GLenum) {
    missing("glBindImageTexture");
}
void glTexBuffer(GLenum, GLenum, GLuint) {
    missing("glTexBuffer");
}
void glTexImage2DMultisample(GLenum, GLsizei, GLenum, GLsizei, GLsizei, GLboolean) {
    missing("glTexImage2DMultisample");
}
void glGetTexLevelParameteriv(GLenum, GLint, GLenum, GLint*) {
    missing("glGetTexLevelParameteriv");
}
void glGetMultisamplefv(GLenum, GLuint, GLfloat*) {
    missing("glGetMultisamplefv");
}
void glQueryCounter(GLuint, GLenum) {
    missing("glQueryCounter");
}
// EXT_disjoint_timer_query_webgl2's reading of a GL_TIME_ELAPSED query (Emscripten's name for it).
void glGetQueryObjectui64vEXT(GLuint id, GLenum pname, GLuint64* params);
void glGetQueryObjectui64v(GLuint id, GLenum pname, GLuint64* params) {
    glGetQueryObjectui64vEXT(id, pname, params);
}
void glGetQueryObjectiv(GLuint id, GLenum pname, GLint* params) {
    GLuint v = 0;
    glGetQueryObjectuiv(id, pname, &v);
    if (params) *params = GLint(v);
}
void glGetBufferSubData(GLenum, GLintptr, GLsizeiptr, void*) {
    missing("glGetBufferSubData");
}
void glClearBufferData(GLenum, GLenum, GLenum, GLenum, void const*) {
    missing("glClearBufferData");
}
void glObjectLabel(GLenum, GLuint, GLsizei, GLchar const*) {}
void glDebugMessageCallback(GLDEBUGPROC, void const*) {
    missing("glDebugMessageCallback");
}
void glDebugMessageControl(GLenum, GLenum, GLenum, GLsizei, GLuint const*, GLboolean) {
    missing("glDebugMessageControl");
}
void glDrawBuffer(GLenum buf) {
    glDrawBuffers(1, &buf);
}
void glPolygonMode(GLenum, GLenum) {
    missing("glPolygonMode");
}
void glClearDepth(double depth) {
    glClearDepthf(float(depth));
}
}
#endif
