// Combine pass of `accumulation: split`: the lighting modes left the sums of diffuse light
// (without albedo) and of specular light in two targets; this adds the surface terms and the
// albedo, the same sum the single-target modes form in registers (docs/lighting.md).
#version 330 core
#include "bindings.glsl"
#include "gbuffer_read.glsl"
#include "surface_terms.glsl"

uniform sampler2D uDiffuseLight;
uniform sampler2D uSpecularLight;
uniform vec3 uAmbient;

out vec4 fragColor;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec3 pos;
    if (!gbufferPosition(px, pos)) { fragColor = vec4(0.0); return; }  // background: nothing was drawn
    vec4 as = gbufferAlbedoSpec(px);
    vec4 ea = gbufferEmissiveAo(px);
    vec3 diffuse = texelFetch(uDiffuseLight, px, 0).rgb;
    vec3 specular = texelFetch(uSpecularLight, px, 0).rgb;
    fragColor = vec4(surfaceTerms(uAmbient, as.rgb, ea.a, ea.rgb) + as.rgb * diffuse + specular, 1.0);
}
