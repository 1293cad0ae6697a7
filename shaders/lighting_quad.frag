// Full-screen lighting: every pixel loops over every light (the first deferred lighting pass).
#version 330 core
#include "lighting.glsl"

uniform sampler2D uPosition;
uniform sampler2D uNormal;
uniform sampler2D uAlbedoSpec;
uniform vec3 uAmbient;
uniform int uLightCount;
uniform samplerBuffer uLights;  // 4 texels per light, see renderer/light_buffer.h

out vec4 fragColor;

Light fetchLight(int i) {
    vec4 a = texelFetch(uLights, i * 4 + 0);
    vec4 b = texelFetch(uLights, i * 4 + 1);
    vec4 c = texelFetch(uLights, i * 4 + 2);
    return Light(a.xyz, b.xyz, c.xyz, a.w, b.w);
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 pos = texelFetch(uPosition, px, 0);
    if (pos.w == 0.0) { fragColor = vec4(0.0); return; }  // background: nothing was drawn
    vec3 n = normalize(texelFetch(uNormal, px, 0).xyz);
    vec4 as = texelFetch(uAlbedoSpec, px, 0);
    vec3 color = uAmbient * as.rgb;
    for (int i = 0; i < uLightCount; ++i) color += shadeLight(fetchLight(i), pos.xyz, n, as.rgb, as.a);
    fragColor = vec4(color, 1.0);
}
