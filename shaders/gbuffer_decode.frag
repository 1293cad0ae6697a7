// Decodes the G-buffer into float position and unit normal through gbuffer_read.glsl, so read-back
// and export see exactly what the lighting read, whatever the layout.
#version 330 core
#include "bindings.glsl"
#include "gbuffer_read.glsl"

uniform ivec2 uPixelOffset;  // G-buffer pixel of this target's (0, 0): one-pixel reads for the inspector

layout(location = 0) out vec4 outPosition;  // xyz world position, w = 1 where geometry was drawn
layout(location = 1) out vec4 outNormal;    // xyz unit normal, w = 1 where drawn

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy) + uPixelOffset;
    vec3 p;
    if (!gbufferPosition(px, p)) {
        outPosition = vec4(0.0);
        outNormal = vec4(0.0);
        return;
    }
    outPosition = vec4(p, 1.0);
    outNormal = vec4(gbufferNormal(px), 1.0);
}
