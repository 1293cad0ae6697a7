// prepass (deferred lighting, docs/deferred_lighting.md): the thin G-buffer. Each opaque surface's
// world normal and specular exponent into one RGBA16F target; its depth goes to the lit target's.
#version 330 core
#include "bindings.glsl"
#include "material.glsl"

in vec3 vNormal;
in vec2 vUV;
in vec4 vTangent;

// The setting: one exponent for every material here (docs/lighting.md), stored per pixel as
// deferred lighting stores it, so the light pass reads it from the thin G-buffer.
uniform float uShininess;

layout(location = 0) out vec4 gNormalExponent;  // xyz unit world normal, w specular exponent

void main() {
    vec4 base = materialBaseColor(vUV);
    if (uAlphaMask && base.a < uAlphaCutoff) discard;  // the G-buffer's cut-outs
    gNormalExponent = vec4(materialNormal(vNormal, vTangent, vUV, gl_FrontFacing), uShininess);
}
