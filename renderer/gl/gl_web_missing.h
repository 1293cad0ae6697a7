// Desktop GL entry points and constants that WebGL2 (OpenGL ES 3.0) lacks, for the web build only
// (gl_api.h includes this under __EMSCRIPTEN__). The functions are defined in gl_web.cpp as no-ops
// that raise GL_INVALID_OPERATION: every caller sits behind a GlCaps flag that is false in WebGL2.
#pragma once

#include <cstdint>

// Compute shaders, storage buffers and image load/store (tiled and clustered lighting).
#define GL_COMPUTE_SHADER 0x91B9
#define GL_SHADER_STORAGE_BUFFER 0x90D2
#define GL_SHADER_STORAGE_BARRIER_BIT 0x00002000
#define GL_SHADER_IMAGE_ACCESS_BARRIER_BIT 0x00000020
#define GL_TEXTURE_FETCH_BARRIER_BIT 0x00000008
#define GL_BUFFER_UPDATE_BARRIER_BIT 0x00000200
#define GL_FRAMEBUFFER_BARRIER_BIT 0x00000400
#define GL_ALL_BARRIER_BITS 0xFFFFFFFF
#define GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS 0x90EB
#define GL_MAX_SHADER_STORAGE_BLOCK_SIZE 0x90DE
#define GL_WRITE_ONLY 0x88B9
#define GL_READ_ONLY 0x88B8
#define GL_READ_WRITE 0x88BA
// Buffer textures (the light buffer is read through one on the desktop).
#define GL_TEXTURE_BUFFER 0x8C2A
#define GL_MAX_TEXTURE_BUFFER_SIZE 0x8C2B
// Timer queries: EXT_disjoint_timer_query_webgl2 offers GL_TIME_ELAPSED where the browser has it
// (gl/gpu_timer.h); GL_TIMESTAMP stays the desktop's.
#define GL_TIME_ELAPSED 0x88BF
#define GL_TIMESTAMP 0x8E28
// Multisample textures (the MSAA G-buffer; WebGL2 has multisampled renderbuffers only).
#define GL_TEXTURE_2D_MULTISAMPLE 0x9100
#define GL_MAX_COLOR_TEXTURE_SAMPLES 0x910E
#define GL_MAX_DEPTH_TEXTURE_SAMPLES 0x910F
// Level queries (ES 3.1): whether a multisample texture got its storage (gpu/msaa_targets.cpp).
#define GL_TEXTURE_WIDTH 0x1000
#define GL_SAMPLE_POSITION 0x8E50
// Occlusion queries that count samples (the msaa detection pass's complex-pixel count); WebGL2 has
// only the any-samples-passed kind, and refuses msaa before the query is made.
#define GL_SAMPLES_PASSED 0x8914
// Pipeline statistics.
#define GL_FRAGMENT_SHADER_INVOCATIONS 0x82F4
#define GL_FRAGMENT_SHADER_INVOCATIONS_ARB 0x82F4
// KHR_debug.
#define GL_DEBUG_OUTPUT 0x92E0
#define GL_DEBUG_OUTPUT_SYNCHRONOUS 0x8242
#define GL_DEBUG_SOURCE_API 0x8246
#define GL_DEBUG_SOURCE_WINDOW_SYSTEM 0x8247
#define GL_DEBUG_SOURCE_SHADER_COMPILER 0x8248
#define GL_DEBUG_SOURCE_THIRD_PARTY 0x8249
#define GL_DEBUG_SOURCE_APPLICATION 0x824A
#define GL_DEBUG_SOURCE_OTHER 0x824B
#define GL_DEBUG_TYPE_ERROR 0x824C
#define GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR 0x824D
#define GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR 0x824E
#define GL_DEBUG_TYPE_PORTABILITY 0x824F
#define GL_DEBUG_TYPE_PERFORMANCE 0x8250
#define GL_DEBUG_TYPE_OTHER 0x8251
#define GL_DEBUG_TYPE_MARKER 0x8268
#define GL_DEBUG_TYPE_PUSH_GROUP 0x8269
#define GL_DEBUG_TYPE_POP_GROUP 0x826A
#define GL_DEBUG_SEVERITY_HIGH 0x9146
#define GL_DEBUG_SEVERITY_MEDIUM 0x9147
#define GL_DEBUG_SEVERITY_LOW 0x9148
#define GL_DEBUG_SEVERITY_NOTIFICATION 0x826B
#define GL_BUFFER 0x82E0
#define GL_SHADER 0x82E1
#define GL_PROGRAM 0x82E2
#define GL_QUERY 0x82E3
#define GL_VERTEX_ARRAY 0x8074
#define GL_TEXTURE 0x1702
#define GL_FRAMEBUFFER_DEFAULT 0x8218
#define GL_CONTEXT_FLAGS 0x821E
#define GL_CONTEXT_FLAG_DEBUG_BIT 0x00000002
// Polygon mode (light-volume wireframes; the issue asks for line geometry instead).
#define GL_LINE 0x1B01
#define GL_FILL 0x1B02
// EXT_texture_norm16's RG16 (the normal_oct layout): the same value; WebGL2 without that extension
// refuses it, and the layout's targets fail to build with the reason.
#define GL_RG16 0x822C
// Desktop-only state.
#define GL_PROGRAM_POINT_SIZE 0x8642
#define GL_TEXTURE_CUBE_MAP_SEAMLESS 0x884F
#define GL_FRAMEBUFFER_SRGB 0x8DB9
#define GL_CLAMP_TO_BORDER 0x812D
#define GL_TEXTURE_BORDER_COLOR 0x1004
#define GL_DEPTH_CLAMP 0x864F
#define GL_STENCIL_INDEX 0x1901  // stencil read-back (WebGL2 reads no stencil)

// Framebuffer status values of desktop GL (named in framebuffer errors).
#define GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER 0x8CDB
#define GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER 0x8CDC
#define GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS 0x8DA8

#ifndef GLAPIENTRY
#define GLAPIENTRY
#endif
typedef void (*GLDEBUGPROC)(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                            GLchar const* message, void const* userParam);

extern "C" {
void glDispatchCompute(GLuint x, GLuint y, GLuint z);
void glMemoryBarrier(GLbitfield barriers);
void glBindImageTexture(GLuint unit, GLuint texture, GLint level, GLboolean layered, GLint layer, GLenum access,
                        GLenum format);
void glTexBuffer(GLenum target, GLenum internalformat, GLuint buffer);
void glTexImage2DMultisample(GLenum target, GLsizei samples, GLenum internalformat, GLsizei width, GLsizei height,
                             GLboolean fixedsamplelocations);
void glGetTexLevelParameteriv(GLenum target, GLint level, GLenum pname, GLint* params);
void glGetMultisamplefv(GLenum pname, GLuint index, GLfloat* val);
void glQueryCounter(GLuint id, GLenum target);
void glGetQueryObjectui64v(GLuint id, GLenum pname, GLuint64* params);
void glGetQueryObjectiv(GLuint id, GLenum pname, GLint* params);
void glGetBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, void* data);
void glClearBufferData(GLenum target, GLenum internalformat, GLenum format, GLenum type, void const* data);
void glObjectLabel(GLenum identifier, GLuint name, GLsizei length, GLchar const* label);
void glDebugMessageCallback(GLDEBUGPROC callback, void const* userParam);
void glDebugMessageControl(GLenum source, GLenum type, GLenum severity, GLsizei count, GLuint const* ids,
                           GLboolean enabled);
void glDrawBuffer(GLenum buf);
void glPolygonMode(GLenum face, GLenum mode);
void glClearDepth(double depth);
}
