// The shader variant of the blit step: writes the G-buffer depth into the bound depth target.
#version 330 core
#include "bindings.glsl"
uniform sampler2D uDepth;
void main() { gl_FragDepth = texelFetch(uDepth, ivec2(gl_FragCoord.xy), 0).r; }
