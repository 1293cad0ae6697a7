// How the normal attachment encodes the unit normal, per layout define (core/gbuffer_layout.h
// sets them; core/octahedral.h is the C++ twin of the octahedral pair). geometry.frag encodes,
// gbuffer_read.glsl decodes.
#ifndef GBL_GBUFFER_ENCODING_GLSL
#define GBL_GBUFFER_ENCODING_GLSL
vec2 octSignNotZero(vec2 v) { return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }

vec2 octEncode(vec3 n) {
    n /= abs(n.x) + abs(n.y) + abs(n.z);
    vec2 p = n.xy;
    if (n.z < 0.0) p = (1.0 - abs(p.yx)) * octSignNotZero(p);
    return p;
}

vec3 octDecode(vec2 e) {
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    float t = max(-n.z, 0.0);
    n.x += n.x >= 0.0 ? -t : t;
    n.y += n.y >= 0.0 ? -t : t;
    return normalize(n);
}

// What the normal attachment stores for the unit normal n.
vec4 encodeNormal(vec3 n) {
#if defined(GBUFFER_NORMAL_OCTAHEDRAL)
    return vec4(octEncode(n) * 0.5 + 0.5, 0.0, 1.0);  // RG16 unorm: [-1, 1] biased to [0, 1]
#elif defined(GBUFFER_NORMAL_BIASED)
    return vec4(n * 0.5 + 0.5, 1.0);
#else
    return vec4(n, 1.0);
#endif
}

// The unit normal back from what the attachment stores.
vec3 decodeNormal(vec4 stored) {
#if defined(GBUFFER_NORMAL_OCTAHEDRAL)
    return octDecode(stored.xy * 2.0 - 1.0);
#elif defined(GBUFFER_NORMAL_BIASED)
    return normalize(stored.xyz * 2.0 - 1.0);
#else
    return normalize(stored.xyz);
#endif
}
#endif
