// Shared vertex stage for every pass that draws scene meshes (G-buffer, forward shading).
#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUV;
layout(location = 3) in vec4 aTangent;
layout(location = 4) in vec2 aUV1;  // TEXCOORD_1 (zero for meshes without one)

uniform mat4 uModel;
uniform mat3 uNormalMatrix;  // inverse-transpose of uModel's upper 3x3
uniform mat4 uViewProj;

out vec3 vWorldPos;
out vec3 vNormal;
out vec2 vUV;
out vec4 vTangent;
out vec2 vUV1;  // read by material.glsl
// The same position in every program that draws a mesh: forward+ shades where its depth pre-pass
// (another program) left exactly this depth.
invariant gl_Position;

void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorldPos = world.xyz;
    vNormal = uNormalMatrix * aNormal;
    // Tangents follow the surface like positions do (model matrix, not the normal matrix).
    vTangent = vec4(mat3(uModel) * aTangent.xyz, aTangent.w);
    vUV = aUV;
    vUV1 = aUV1;
    gl_Position = uViewProj * world;
}
