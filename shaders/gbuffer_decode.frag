// Decodes the G-buffer into float position and unit normal through gbuffer_read.glsl, so read-back
// and export see exactly what the lighting read, whatever the layout.
// msaa variants (docs/msaa.md), GBL_MSAA_SAMPLES n: sample uSample decoded, with its albedo and
// specular and its emission and occlusion too (the editor's sample views and pixel inspector); with
// GBL_MSAA_COUNTS, the number of distinct surfaces among the pixel's samples instead
// (msaa_edges.glsl, the detection's own test: the samples heat map).
#version 330 core
#include "bindings.glsl"
#include "gbuffer_read.glsl"
#ifdef GBL_MSAA_COUNTS
uniform vec3 uViewPos;  // the eye the position threshold is relative to
#include "msaa_edges.glsl"
#endif

uniform ivec2 uPixelOffset;  // G-buffer pixel of this target's (0, 0): one-pixel reads for the inspector

layout(location = 0) out vec4 outPosition;  // xyz world position, w = 1 where geometry was drawn
layout(location = 1) out vec4 outNormal;    // xyz unit normal, w = 1 where drawn
#ifdef GBL_MSAA_SAMPLES
uniform int uSample;                          // the sample decoded
layout(location = 2) out vec4 outAlbedoSpec;  // linear albedo rgb, specular a
layout(location = 3) out vec4 outEmissiveAo;  // emitted radiance rgb, occlusion a
#endif

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy) + uPixelOffset;
#if defined(GBL_MSAA_COUNTS)
    outPosition = vec4(float(msaaDistinctSurfaces(px)), 0.0, 0.0, 1.0);  // the count in red
    outNormal = vec4(0.0);
    outAlbedoSpec = vec4(0.0);
    outEmissiveAo = vec4(0.0);
    return;
#elif defined(GBL_MSAA_SAMPLES)
    gSample = uSample;
    outAlbedoSpec = gbufferAlbedoSpec(px);
    outEmissiveAo = gbufferEmissiveAo(px);
#endif
    vec3 p;
    if (!gbufferPosition(px, p)) {
        outPosition = vec4(0.0);
        outNormal = vec4(0.0);
        return;
    }
    outPosition = vec4(p, 1.0);
    outNormal = vec4(gbufferNormal(px), 1.0);
}
