// Full-screen lighting: every pixel loops over every light (the first deferred lighting pass).
#version 330 core
#include "bindings.glsl"
#include "lighting.glsl"
#include "light_fetch.glsl"
#include "gbuffer_read.glsl"

uniform vec3 uAmbient;
uniform int uLightCount;

out vec4 fragColor;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec3 pos;
    if (!gbufferPosition(px, pos)) { fragColor = vec4(0.0); return; }  // background: nothing was drawn
    vec3 n = gbufferNormal(px);
    vec4 as = gbufferAlbedoSpec(px);
    vec3 color = uAmbient * as.rgb;
    color += shadeGlobalLights(pos, n, as.rgb, as.a);  // directional lights: no volume, every pixel
    for (int i = 0; i < uLightCount; ++i) {
        // Distance test on the first texel alone: most lights are out of reach of most pixels.
        vec4 pr = texelFetch(uLights, i * 4);
        if (distance(pr.xyz, pos) >= pr.w) continue;
        color += shadeLight(fetchLight(i), pos, n, as.rgb, as.a);
    }
    fragColor = vec4(color, 1.0);
}
