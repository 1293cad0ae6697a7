// Light cubes are emissive: their HDR colour, unlit, tonemapped as the lit image is, since they are
// drawn onto the display image after the view pass (not into the lit image, which holds the light sum).
#version 330 core
#include "view_constants.glsl"
#include "tonemap.glsl"
flat in vec3 vColor;
uniform float uEmissive;  // HDR brightness so the cubes stay saturated after tonemapping
out vec4 fragColor;
void main() { fragColor = vec4(tonemap(vColor * uEmissive), 1.0); }
