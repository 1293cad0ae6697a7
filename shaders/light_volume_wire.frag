// Light-volume wireframes: each light's enclosing sphere drawn as lines in the light's colour, on the
// display image after the view pass, tonemapped as the lit image is.
#version 330 core
#include "bindings.glsl"
#include "lighting.glsl"
#include "light_fetch.glsl"
#include "view_constants.glsl"
#include "tonemap.glsl"

flat in int vLight;
uniform float uWireIntensity;  // HDR brightness, so the lines survive tonemapping
out vec4 fragColor;

void main() { fragColor = vec4(tonemap(fetchLightColor(vLight) * uWireIntensity), 1.0); }
