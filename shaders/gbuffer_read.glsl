// Reads the surface a G-buffer pixel holds. Every lighting shader goes through these functions,
// so they are the one place that knows how the G-buffer stores position, normal and material.
#ifndef GBL_GBUFFER_READ_GLSL
#define GBL_GBUFFER_READ_GLSL
uniform sampler2D uPosition;
uniform sampler2D uNormal;
uniform sampler2D uAlbedoSpec;

// The world position at px; false where no geometry was drawn (the background).
bool gbufferPosition(ivec2 px, out vec3 position) {
    vec4 p = texelFetch(uPosition, px, 0);
    position = p.xyz;
    return p.w != 0.0;
}

// The unit world normal at px.
vec3 gbufferNormal(ivec2 px) { return normalize(texelFetch(uNormal, px, 0).xyz); }

// Linear albedo (rgb) and specular intensity (a) at px.
vec4 gbufferAlbedoSpec(ivec2 px) { return texelFetch(uAlbedoSpec, px, 0); }
#endif
