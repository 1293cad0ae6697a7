// Reads one light from the light buffer texture (layout in renderer/gpu/light_buffer.h).
#include "shader_checks.glsl"
#include "light_texels.glsl"

// Directional lights, shaded by every mode's full-screen loop (shadeGlobalLights below): their
// indices in the light buffer, set by bindLights() (renderer/passes/shading_inputs.cpp).
#define MAX_DIRECTIONAL_LIGHTS 8
uniform int uDirectionalCount;
uniform int uDirectionalLights[MAX_DIRECTIONAL_LIGHTS];

// The octahedral direction of texel 3 (core/octahedral.h's octDecode).
vec3 lightDirectionDecode(vec2 e) {
    vec3 v = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    float t = max(-v.z, 0.0);
    v.xy += vec2(v.x >= 0.0 ? -t : t, v.y >= 0.0 ? -t : t);
    return normalize(v);
}

// Loops that visit every light take LIGHTS_PER_ITERATION lights an iteration. Mesa's llvmpipe
// ends a shader invocation's loops after 65,535 iterations counted over all of its loops together
// (gallivm's loop limiter), with no error: a plain loop over more lights than that silently drops
// the rest (at 262,144 lights clustered's over-cap pixels lost lights that way). Eight an
// iteration keeps kMaxLights (262,144) at 32,768 iterations, with room for the shader's other
// loops. tests/many_lights_gl_test.cpp ("MoreLightsThanOneShaderMayLoopOver") checks it.
#define LIGHTS_PER_ITERATION 8
// FOR_EVERY_LIGHT(count, STEP) calls STEP(i) for i = 0 .. count - 1 in order, 8 an iteration; STEP
// is a one-line macro the caller defines (e.g. #define ADD(j) addLight(j, ...)). One line, since
// GLSL 3.30 has no line continuation.
#define FOR_EVERY_LIGHT(count, STEP) { int i_ = 0; for (; i_ + LIGHTS_PER_ITERATION <= (count); i_ += LIGHTS_PER_ITERATION) { STEP(i_); STEP(i_ + 1); STEP(i_ + 2); STEP(i_ + 3); STEP(i_ + 4); STEP(i_ + 5); STEP(i_ + 6); STEP(i_ + 7); } for (; i_ < (count); ++i_) STEP(i_); }

Light fetchLight(int i) {
    i = CHECKED(CHECK_SITE_LIGHT_TEXEL, i, lightTexelCount() / 4);
    vec4 a = lightTexel(i * 4 + 0);
    vec4 b = lightTexel(i * 4 + 1);
    vec4 c = lightTexel(i * 4 + 2);
    vec4 d = lightTexel(i * 4 + 3);
    return Light(a.xyz, b.xyz, c.xyz, a.w, b.w, lightDirectionDecode(d.yz), c.w, d.w);
}

// The light's colour without intensity (0..1, 8 bits a channel), for wireframes.
vec3 unpackLightWireColor(float bits) {
    float v = bits;
    vec3 c;
    c.r = mod(v, 256.0);
    v = floor(v / 256.0);
    c.g = mod(v, 256.0);
    c.b = floor(v / 256.0);
    return c / 255.0;
}
vec3 fetchLightColor(int i) { return unpackLightWireColor(lightTexel(i * 4 + 3).x); }

// Every directional light at a surface point: the "global lights in one full-screen pass" half
// of the split (local lights are culled by radius, volumes or tiles; these reach every pixel).
vec3 shadeGlobalLights(vec3 p, vec3 n, vec3 albedo, float specular) {
    vec3 sum = vec3(0.0);
    for (int k = 0; k < min(uDirectionalCount, MAX_DIRECTIONAL_LIGHTS); ++k) sum += shadeDirectional(fetchLight(uDirectionalLights[k]), p, n, albedo, specular);
    return sum;
}

// The cone half of the tile and cluster tests (core/spot_cull.h's sphereMayTouchCone is the CPU
// twin): false only when a view-space sphere (centre s, radius sr) around the tile's or cluster's
// pixels cannot meet light i's cone (apex at its view-space position, along its direction, outer
// angle); always true for point lights. Run after the sphere test, which bounds the range.
bool coneMayTouchSphere(int i, mat3 view, vec3 apexView, vec3 s, float sr) {
    vec4 c = lightTexel(i * 4 + 2);
    if (c.w < -1.5) return true;  // no cone
    vec3 axis = view * lightDirectionDecode(lightTexel(i * 4 + 3).yz);
    vec3 v = s - apexView;
    float along = dot(v, axis);
    float across = length(v - along * axis);
    float sinOuter = sqrt(max(1.0 - c.w * c.w, 0.0));
    // A hair of slack, as the cluster box test has: rounding never drops a lit pixel.
    float slack = sr * 1.0001 + 1e-4;
    return along >= -slack && c.w * across - along * sinOuter <= slack;
}
