// Geometry pass: writes world position, world normal and albedo/specular into the G-buffer.
#version 330 core
#include "bindings.glsl"
#include "material.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUV;
in vec4 vTangent;

layout(location = 0) out vec4 gPosition;    // xyz world position, w = 1 where geometry was drawn
layout(location = 1) out vec4 gNormal;      // xyz world normal (unit), w = 1 where drawn
layout(location = 2) out vec4 gAlbedoSpec;  // rgb linear albedo, a = specular intensity

void main() {
    vec4 base = materialBaseColor(vUV);
    if (uAlphaMask && base.a < uAlphaCutoff) discard;  // alpha-mask materials are cut-outs
    gPosition = vec4(vWorldPos, 1.0);
    gNormal = vec4(materialNormal(vNormal, vTangent, vUV, gl_FrontFacing), 1.0);
    gAlbedoSpec = vec4(base.rgb, materialSpecular(vUV));
}
