// Copies a texture's texels into a float target, one texel per pixel. The browser build reads
// depth back this way: WebGL2 reads colour attachments only, so the depth texture is drawn into
// an RGBA32F one first (renderer/renderer_readback.cpp).
#version 330 core
#include "bindings.glsl"
uniform sampler2D uReadbackSource;
layout(location = 0) out vec4 oTexel;
void main() { oTexel = texelFetch(uReadbackSource, ivec2(gl_FragCoord.xy), 0); }
