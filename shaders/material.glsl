// Material sampling shared by the geometry pass and the forward passes.
uniform sampler2D uBaseColorTex;
uniform bool uHasBaseColorTex;
uniform vec4 uBaseColorFactor;
uniform sampler2D uNormalTex;
uniform bool uHasNormalTex;
uniform float uNormalScale;
uniform sampler2D uSpecularTex;
uniform bool uHasSpecularTex;
uniform float uSpecularFactor;
uniform bool uAlphaMask;
uniform float uAlphaCutoff;
uniform bool uUseNormalMaps;

vec4 materialBaseColor(vec2 uv) {
    vec4 c = uBaseColorFactor;
    if (uHasBaseColorTex) c *= texture(uBaseColorTex, uv);  // sRGB texture: sampled as linear
    return c;
}

float materialSpecular(vec2 uv) {
    float s = uSpecularFactor;
    if (uHasSpecularTex) s *= texture(uSpecularTex, uv).r;
    return s;
}

// World-space shading normal: the interpolated normal, bent by the normal map through TBN.
vec3 materialNormal(vec3 normal, vec4 tangent, vec2 uv, bool frontFacing) {
    vec3 n = normalize(normal);
    if (!frontFacing) n = -n;  // double-sided surfaces seen from behind
    if (!uHasNormalTex || !uUseNormalMaps) return n;
    vec3 t = normalize(tangent.xyz - n * dot(n, tangent.xyz));  // Gram-Schmidt
    vec3 b = cross(n, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
    vec3 m = texture(uNormalTex, uv).xyz * 2.0 - 1.0;
    m.xy *= uNormalScale;
    return normalize(mat3(t, b, n) * m);
}
