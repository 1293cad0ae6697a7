// Copies a texture's texels into a float target, one texel per pixel, or writes one constant. The
// browser build reads depth and stencil back this way (renderer/renderer_readback.cpp): WebGL2
// reads colour attachments only, so the depth texture is drawn into an RGBA32F one first, and the
// stencil bits are summed into an RGBA8 one, a pass per bit plane, through the stencil test.
#version 330 core
#include "bindings.glsl"
uniform sampler2D uReadbackSource;
uniform bool uWriteConstant;  // write uConstant instead of the source's texel
uniform vec4 uConstant;
layout(location = 0) out vec4 oTexel;
void main() { oTexel = uWriteConstant ? uConstant : texelFetch(uReadbackSource, ivec2(gl_FragCoord.xy), 0); }
