// prepass (deferred lighting, docs/deferred_lighting.md): the second geometry pass. Each opaque
// surface again, where the thin pass left its depth, its material applied to the light summed at
// its pixel: the surface terms, albedo * diffuse light, specular intensity * specular light.
#version 330 core
#include "bindings.glsl"
#include "material.glsl"
#include "surface_terms.glsl"

in vec2 vUV;

uniform sampler2D uDiffuseLight;
uniform sampler2D uSpecularLight;
uniform vec3 uAmbient;

out vec4 fragColor;

void main() {
    vec4 base = materialBaseColor(vUV);
    if (uAlphaMask && base.a < uAlphaCutoff) discard;  // the thin pass's cut-outs
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec3 diffuse = texelFetch(uDiffuseLight, px, 0).rgb;
    vec3 specular = texelFetch(uSpecularLight, px, 0).rgb;
    vec3 surface = surfaceTerms(uAmbient, base.rgb, materialOcclusion(vUV), materialEmissive(vUV));
    fragColor = vec4(surface + base.rgb * diffuse + materialSpecular(vUV) * specular, 1.0);
}
