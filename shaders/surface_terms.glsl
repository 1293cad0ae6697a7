// The light-independent terms of docs/lighting.md, added once per pixel by every lighting mode:
// the ambient light the surface's occlusion lets through, and the light it emits.
#ifndef GBL_SURFACE_TERMS_GLSL
#define GBL_SURFACE_TERMS_GLSL
uniform float uEmissiveWeight;  // 1; 0 in a frame that shows one light's contribution alone

vec3 surfaceTerms(vec3 ambient, vec3 albedo, float occlusion, vec3 emissive) {
    return ambient * albedo * occlusion + emissive * uEmissiveWeight;
}
#endif
