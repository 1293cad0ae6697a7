// The OpenGL declarations every GL-calling source includes: libepoxy on the desktop, WebGL2 (OpenGL
// ES 3.0 through Emscripten) in the browser (issue 29). The one place the two differ in headers.
#pragma once

#ifdef __EMSCRIPTEN__
#include <GLES3/gl3.h>

#include <GLES2/gl2ext.h>
// Entry points and constants of desktop GL 4.x that WebGL2 lacks. The renderer only reaches them
// behind a capability GlCaps reports absent here (compute, KHR_debug, buffer textures, timer
// queries, polygon mode); gl_web.cpp defines the functions as no-ops that raise GL_INVALID_OPERATION.
#include "gl/gl_web_missing.h"
#else
#include <epoxy/gl.h>
#endif

namespace gbl::gl {

// The browser build: WebGL2 through Emscripten.
#ifdef __EMSCRIPTEN__
inline constexpr bool kWebGL2 = true;
#else
inline constexpr bool kWebGL2 = false;
#endif

// Buffer textures (samplerBuffer): the light buffer is one where they exist. WebGL2 has none, so there
// it is a 2D RGBA32F texture kLightTexelsPerRow wide (gpu/light_buffer.h, shaders/light_texels.glsl).
#ifdef __EMSCRIPTEN__
inline constexpr bool kBufferTextures = false;
#else
inline constexpr bool kBufferTextures = true;
#endif
inline constexpr int kLightTexelsPerRow = 1024;
// Shaders are written as GLSL 3.30 core; in WebGL2 the shader library compiles them as GLSL ES 3.00
// (ShaderLibrary::setEsProfile).
#ifdef __EMSCRIPTEN__
inline constexpr bool kGlslEs = true;
#else
inline constexpr bool kGlslEs = false;
#endif

// Whether the current context offers the extension (the GL_ prefix as the desktop spells it).
bool hasExtension(char const* name);
// The current context's version as major * 10 + minor (WebGL2: 30).
int contextVersion();

}  // namespace gbl::gl
