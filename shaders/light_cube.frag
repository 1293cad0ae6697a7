// Light cubes are emissive: their colour is written to the HDR target unlit.
#version 330 core
flat in vec3 vColor;
uniform float uEmissive;  // HDR brightness so the cubes stay saturated after tonemapping
out vec4 fragColor;
void main() { fragColor = vec4(vColor * uEmissive, 1.0); }
