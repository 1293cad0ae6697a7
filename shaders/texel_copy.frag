// Copies a texture's texels into a float target, one texel per pixel, or writes one constant. The
// browser build reads depth and stencil back this way (renderer/renderer_readback.cpp): WebGL2
// reads colour attachments only, so the depth texture is drawn into an RGBA32F one first, and the
// stencil bits are summed into an RGBA8 one, a pass per bit plane, through the stencil test.
#version 330 core
#include "bindings.glsl"
// GBL_MSAA_SAMPLE_COPY (a desktop variant): the source is multisampled and sample uSample is copied
// (Renderer::readMsaaSample, docs/msaa.md).
#ifdef GBL_MSAA_SAMPLE_COPY
uniform sampler2DMS uReadbackSource;
uniform int uSample;
#define READ_TEXEL(p) texelFetch(uReadbackSource, p, uSample)
#else
uniform sampler2D uReadbackSource;
#define READ_TEXEL(p) texelFetch(uReadbackSource, p, 0)
#endif
uniform bool uWriteConstant;  // write uConstant instead of the source's texel
uniform vec4 uConstant;
layout(location = 0) out vec4 oTexel;
void main() { oTexel = uWriteConstant ? uConstant : READ_TEXEL(ivec2(gl_FragCoord.xy)); }
