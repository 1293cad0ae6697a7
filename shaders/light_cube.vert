// One small cube per light, placed and coloured from the light buffer by instance id.
#version 330 core
#include "bindings.glsl"
layout(location = 0) in vec3 aPosition;
uniform mat4 uViewProj;
uniform float uCubeSize;
#include "light_texels.glsl"
flat out vec3 vColor;
void main() {
    vec4 a = lightTexel(gl_InstanceID * 4 + 0);
    vec4 d = lightTexel(gl_InstanceID * 4 + 3);
    // The light's colour, 0..1: the packed wire colour of shaders/light_fetch.glsl.
    vColor = vec3(mod(d.x, 256.0), mod(floor(d.x / 256.0), 256.0), floor(d.x / 65536.0)) / 255.0;
    gl_Position = uViewProj * vec4(a.xyz + aPosition * uCubeSize, 1.0);
}
