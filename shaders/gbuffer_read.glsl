// Reads the surface a G-buffer pixel holds. Every lighting shader goes through these functions,
// so they are the one place that knows how the G-buffer stores position, normal and material
// (the layout's defines from core/gbuffer_layout.h choose; gbuffer_encoding.glsl decodes normals).
#ifndef GBL_GBUFFER_READ_GLSL
#define GBL_GBUFFER_READ_GLSL
#include "gbuffer_encoding.glsl"
uniform sampler2D uPosition;
uniform sampler2D uNormal;
uniform sampler2D uAlbedoSpec;
uniform sampler2D uEmissiveAo;    // emitted radiance rgb, ambient occlusion a
uniform sampler2D uDepth;         // the G-buffer's depth (window space, 1 = background)
uniform mat4 uInverseViewProj;  // for layouts that rebuild position from depth

// The world position at px; false where no geometry was drawn (the background).
bool gbufferPosition(ivec2 px, out vec3 position) {
#ifdef GBUFFER_POSITION_FROM_DEPTH
    float d = texelFetch(uDepth, px, 0).r;
    vec2 ndc = (vec2(px) + 0.5) / vec2(textureSize(uDepth, 0)) * 2.0 - 1.0;
    vec4 world = uInverseViewProj * vec4(ndc, d * 2.0 - 1.0, 1.0);
    position = world.xyz / world.w;
    return d < 1.0;  // the geometry pass clears depth to 1 and draws with GL_LESS
#else
    vec4 p = texelFetch(uPosition, px, 0);
    position = p.xyz;
    return p.w != 0.0;
#endif
}

// The unit world normal at px.
vec3 gbufferNormal(ivec2 px) { return decodeNormal(texelFetch(uNormal, px, 0)); }

// Linear albedo (rgb) and specular intensity (a) at px.
vec4 gbufferAlbedoSpec(ivec2 px) { return texelFetch(uAlbedoSpec, px, 0); }

// Emitted radiance (rgb) and ambient occlusion (a) at px. A layout without the emissive_ao
// attachment (packed) stores neither: no emission, no occlusion.
vec4 gbufferEmissiveAo(ivec2 px) {
#ifdef GBUFFER_NO_EMISSIVE_AO
    return vec4(0.0, 0.0, 0.0, 1.0);
#else
    return texelFetch(uEmissiveAo, px, 0);
#endif
}

// Colour attachment `index` of the layout exactly as stored (the order of core/gbuffer_layout.h);
// zero past the layout's last one.
vec4 gbufferRawAttachment(ivec2 px, int index) {
#ifdef GBUFFER_POSITION_FROM_DEPTH
    if (index == 0) return texelFetch(uNormal, px, 0);
    if (index == 1) return texelFetch(uAlbedoSpec, px, 0);
#ifndef GBUFFER_NO_EMISSIVE_AO
    if (index == 2) return texelFetch(uEmissiveAo, px, 0);
#endif
#else
    if (index == 0) return texelFetch(uPosition, px, 0);
    if (index == 1) return texelFetch(uNormal, px, 0);
    if (index == 2) return texelFetch(uAlbedoSpec, px, 0);
    if (index == 3) return texelFetch(uEmissiveAo, px, 0);
#endif
    return vec4(0.0);
}
#endif
