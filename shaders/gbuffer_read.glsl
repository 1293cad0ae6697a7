// Reads the surface a G-buffer pixel holds. Every lighting shader goes through these functions,
// so they are the one place that knows how the G-buffer stores position, normal and material
// (the layout's defines from core/gbuffer_layout.h choose; gbuffer_encoding.glsl decodes normals).
#ifndef GBL_GBUFFER_READ_GLSL
#define GBL_GBUFFER_READ_GLSL
#include "gbuffer_encoding.glsl"
// GBL_MSAA_SAMPLES n (a variant, docs/msaa.md): the G-buffer is multisampled and every read takes
// sample gSample of the pixel. Desktop GL only: WebGL2 has no multisample textures and never builds it.
#ifdef GBL_MSAA_SAMPLES
#define GBUFFER_SAMPLER sampler2DMS
// Below 0: the pixel lit once (the edges strategy's simple pixels): sample 0's attributes, at the
// pixel's centre (gbufferPosition).
int gSample = 0;
// Where each sample lies in its pixel (0..1; glGetMultisamplefv, read when the targets were made):
// a layout that rebuilds position unprojects sample k's depth at sample k's own place.
uniform vec2 uSamplePositions[GBL_MSAA_SAMPLES];
#define GBUFFER_SAMPLE_OFFSET uSamplePositions[max(gSample, 0)]
#define GBUFFER_FETCH(t, p) texelFetch(t, p, max(gSample, 0))
#define GBUFFER_SIZE(t) textureSize(t)
#else
#define GBUFFER_SAMPLER sampler2D
#define GBUFFER_SAMPLE_OFFSET vec2(0.5)
#define GBUFFER_FETCH(t, p) texelFetch(t, p, 0)
#define GBUFFER_SIZE(t) textureSize(t, 0)
#endif
uniform GBUFFER_SAMPLER uPosition;
uniform GBUFFER_SAMPLER uNormal;
uniform GBUFFER_SAMPLER uAlbedoSpec;
uniform GBUFFER_SAMPLER uEmissiveAo;  // emitted radiance rgb, ambient occlusion a
uniform GBUFFER_SAMPLER uDepth;       // the G-buffer's depth (window space, 1 = background)
uniform mat4 uInverseViewProj;  // for layouts that rebuild position from depth

// The world position at px; false where no geometry was drawn (the background).
bool gbufferPosition(ivec2 px, out vec3 position) {
#ifdef GBUFFER_POSITION_FROM_DEPTH
    float d = GBUFFER_FETCH(uDepth, px).r;
    vec2 at = GBUFFER_SAMPLE_OFFSET;
#ifdef GBL_MSAA_SAMPLES
    if (gSample < 0) {
        // A simple pixel: one plane under every sample, whose window depth is linear on the screen,
        // so the samples' mean depth lies at their mean place (the centre, as a stored position is).
        d = 0.0;
        at = vec2(0.0);
        for (int i = 0; i < GBL_MSAA_SAMPLES; ++i) {
            d += texelFetch(uDepth, px, i).r;
            at += uSamplePositions[i];
        }
        d /= float(GBL_MSAA_SAMPLES);
        at /= float(GBL_MSAA_SAMPLES);
    }
#endif
    vec2 ndc = (vec2(px) + at) / vec2(GBUFFER_SIZE(uDepth)) * 2.0 - 1.0;
    vec4 world = uInverseViewProj * vec4(ndc, d * 2.0 - 1.0, 1.0);
    position = world.xyz / world.w;
    return d < 1.0;  // the geometry pass clears depth to 1 and draws with GL_LESS
#else
    vec4 p = GBUFFER_FETCH(uPosition, px);
    position = p.xyz;
    return p.w != 0.0;
#endif
}

// The unit world normal at px.
vec3 gbufferNormal(ivec2 px) { return decodeNormal(GBUFFER_FETCH(uNormal, px)); }

// Linear albedo (rgb) and specular intensity (a) at px.
vec4 gbufferAlbedoSpec(ivec2 px) { return GBUFFER_FETCH(uAlbedoSpec, px); }

// Emitted radiance (rgb) and ambient occlusion (a) at px. A layout without the emissive_ao
// attachment (packed) stores neither: no emission, no occlusion.
vec4 gbufferEmissiveAo(ivec2 px) {
#ifdef GBUFFER_NO_EMISSIVE_AO
    return vec4(0.0, 0.0, 0.0, 1.0);
#else
    return GBUFFER_FETCH(uEmissiveAo, px);
#endif
}

// Colour attachment `index` of the layout exactly as stored (the order of core/gbuffer_layout.h);
// zero past the layout's last one.
vec4 gbufferRawAttachment(ivec2 px, int index) {
#ifdef GBUFFER_POSITION_FROM_DEPTH
    if (index == 0) return GBUFFER_FETCH(uNormal, px);
    if (index == 1) return GBUFFER_FETCH(uAlbedoSpec, px);
#ifndef GBUFFER_NO_EMISSIVE_AO
    if (index == 2) return GBUFFER_FETCH(uEmissiveAo, px);
#endif
#else
    if (index == 0) return GBUFFER_FETCH(uPosition, px);
    if (index == 1) return GBUFFER_FETCH(uNormal, px);
    if (index == 2) return GBUFFER_FETCH(uAlbedoSpec, px);
    if (index == 3) return GBUFFER_FETCH(uEmissiveAo, px);
#endif
    return vec4(0.0);
}
#endif
