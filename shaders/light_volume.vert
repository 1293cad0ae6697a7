// Light volumes: one instance of the unit sphere per light, scaled to the light's radius times
// the enclosing scale (renderer/light_volume_mesh.h) so the mesh covers the whole true sphere.
#version 330 core
#include "bindings.glsl"
layout(location = 0) in vec3 aPosition;  // unit-sphere vertex

uniform mat4 uViewProj;
uniform float uEnclosingScale;
uniform samplerBuffer uLights;
uniform isamplerBuffer uInstances;  // light index per instance
uniform int uFirstInstance;         // offset into uInstances (draws of one light or one group)

flat out int vLight;

void main() {
    int light = texelFetch(uInstances, uFirstInstance + gl_InstanceID).r;
    vec4 positionRadius = texelFetch(uLights, light * 4);
    vLight = light;
    gl_Position = uViewProj * vec4(positionRadius.xyz + aPosition * (positionRadius.w * uEnclosingScale), 1.0);
}
