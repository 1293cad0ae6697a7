// Light volumes: one instance of the unit sphere per light, scaled to the light's radius times
// the enclosing scale (renderer/core/light_volume_mesh.h) so the mesh covers the whole true
// sphere; or, with uCone, one instance of the unit cone per spot light, its apex at the light,
// along the spot's direction, as tall as the radius and as wide as the outer angle times the
// cone's radial scale (renderer/core/light_volume_cone.h: coneVolume, the CPU twin); or, with
// uArrow (wireframes), an arrow along each directional light's direction.
#version 330 core
#include "bindings.glsl"
#include "lighting.glsl"
#include "light_fetch.glsl"
layout(location = 0) in vec3 aPosition;  // unit-sphere or unit-cone vertex

uniform mat4 uViewProj;
uniform float uEnclosingScale;
uniform bool uCone;
uniform float uConeRadialScale;
uniform float uVolumeScale;
uniform bool uArrow;         // wireframes: instance k is the k-th directional light's arrow
uniform float uArrowLength;
uniform int uFirstInstance;  // offset into uInstances (draws of one light or one group)
// The light index per instance: a buffer texture, or without them (WebGL2) a 2D R32I texture in
// rows of GBL_LIGHT_TEXELS_PER_ROW (renderer/passes/light_volumes.cpp).
#ifdef GBL_NO_BUFFER_TEXTURES
uniform highp isampler2D uInstances;
int instanceLight(int i) { return texelFetch(uInstances, ivec2(i % GBL_LIGHT_TEXELS_PER_ROW, i / GBL_LIGHT_TEXELS_PER_ROW), 0).r; }
#else
uniform isamplerBuffer uInstances;
int instanceLight(int i) { return texelFetch(uInstances, i).r; }
#endif

flat out int vLight;

// The two unit vectors across the axis (core/light_volume_cone.cpp's coneBasis).
void coneBasis(vec3 axis, out vec3 x, out vec3 y) {
    vec3 helper = abs(axis.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    x = normalize(cross(helper, axis));
    y = cross(axis, x);
}

void main() {
    int light = uArrow ? uDirectionalLights[gl_InstanceID] : instanceLight(uFirstInstance + gl_InstanceID);
    vec4 positionRadius = lightTexel(light * 4);
    vLight = light;
    vec3 world;
    if (uArrow) {
        Light l = fetchLight(light);
        vec3 x, y;
        coneBasis(l.direction, x, y);
        world = positionRadius.xyz + (x * aPosition.x + y * aPosition.y + l.direction * aPosition.z) * uArrowLength;
    } else if (uCone) {
        Light l = fetchLight(light);
        float height = positionRadius.w * uVolumeScale;
        float sinOuter = sqrt(max(1.0 - l.cosOuter * l.cosOuter, 0.0));
        float ring = height * sinOuter / l.cosOuter * uConeRadialScale;
        vec3 x, y;
        coneBasis(l.direction, x, y);
        world = positionRadius.xyz + (x * aPosition.x + y * aPosition.y) * ring + l.direction * (aPosition.z * height);
    } else {
        world = positionRadius.xyz + aPosition * (positionRadius.w * uEnclosingScale);
    }
    gl_Position = uViewProj * vec4(world, 1.0);
}
