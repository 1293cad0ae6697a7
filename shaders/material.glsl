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
uniform vec3 uEmissiveFactor;
uniform sampler2D uEmissiveTex;  // sRGB: sampled as linear
uniform bool uHasEmissiveTex;
uniform sampler2D uOcclusionTex;
uniform bool uHasOcclusionTex;
uniform float uOcclusionStrength;

// Per texture: which coordinate set it reads (0 = TEXCOORD_0, 1 = TEXCOORD_1) and its
// KHR_texture_transform matrix (renderer/scene/texture_transform.h; identity without one).
uniform int uBaseColorTexCoord;
uniform mat3 uBaseColorUvTransform;
uniform int uNormalTexCoord;
uniform mat3 uNormalUvTransform;
uniform int uSpecularTexCoord;
uniform mat3 uSpecularUvTransform;
uniform int uEmissiveTexCoord;
uniform mat3 uEmissiveUvTransform;
uniform int uOcclusionTexCoord;
uniform mat3 uOcclusionUvTransform;

// TEXCOORD_1 from mesh.vert. The passes hand the functions below TEXCOORD_0 (vUV) and each
// texture picks its own set here, so a second set changes no pass's shader.
in vec2 vUV1;

vec2 materialTexCoord(int set, mat3 transform, vec2 uv0) {
    vec2 uv = set == 1 ? vUV1 : uv0;
    return (transform * vec3(uv, 1.0)).xy;
}

vec4 materialBaseColor(vec2 uv) {
    vec4 c = uBaseColorFactor;
    if (uHasBaseColorTex)  // sRGB texture: sampled as linear
        c *= texture(uBaseColorTex, materialTexCoord(uBaseColorTexCoord, uBaseColorUvTransform, uv));
    return c;
}

float materialSpecular(vec2 uv) {
    float s = uSpecularFactor;
    if (uHasSpecularTex) s *= texture(uSpecularTex, materialTexCoord(uSpecularTexCoord, uSpecularUvTransform, uv)).r;
    return s;
}

// Emitted radiance: emissiveFactor times the emissive texture (glTF 2.0).
vec3 materialEmissive(vec2 uv) {
    vec3 e = uEmissiveFactor;
    if (uHasEmissiveTex) e *= texture(uEmissiveTex, materialTexCoord(uEmissiveTexCoord, uEmissiveUvTransform, uv)).rgb;
    return e;
}

// Ambient occlusion: 1 + strength * (texture.r - 1) (glTF 2.0), 1 without a texture.
float materialOcclusion(vec2 uv) {
    if (!uHasOcclusionTex) return 1.0;
    float ao = texture(uOcclusionTex, materialTexCoord(uOcclusionTexCoord, uOcclusionUvTransform, uv)).r;
    return 1.0 + uOcclusionStrength * (ao - 1.0);
}

// World-space shading normal: the interpolated normal, bent by the normal map through TBN.
vec3 materialNormal(vec3 normal, vec4 tangent, vec2 uv, bool frontFacing) {
    vec3 n = normalize(normal);
    if (!frontFacing) n = -n;  // double-sided surfaces seen from behind
    if (!uHasNormalTex || !uUseNormalMaps) return n;
    vec3 t = normalize(tangent.xyz - n * dot(n, tangent.xyz));  // Gram-Schmidt
    vec3 b = cross(n, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
    vec3 m = texture(uNormalTex, materialTexCoord(uNormalTexCoord, uNormalUvTransform, uv)).xyz * 2.0 - 1.0;
    m.xy *= uNormalScale;
    return normalize(mat3(t, b, n) * m);
}
