// Import pass: writes a G-buffer another program wrote (decoded to world space on the CPU by
// renderer/import) into the current layout's attachments, through the geometry pass's own encoding
// (gbuffer_encoding.glsl), so every layout re-lights it as it would the scene, emission and occlusion
// included where the layout stores them. Background pixels are discarded and keep the cleared values.
#version 330 core
#include "bindings.glsl"
#include "gbuffer_encoding.glsl"

uniform sampler2D uImportPositionDepth;  // xyz world position, w window depth (1: background)
uniform sampler2D uImportNormal;         // xyz world normal
uniform sampler2D uImportAlbedoSpec;     // rgb linear albedo, a specular intensity
uniform sampler2D uImportEmissiveAo;     // rgb linear emitted radiance, a ambient occlusion

#ifdef GBUFFER_POSITION_FROM_DEPTH
layout(location = 0) out vec4 gNormal;
layout(location = 1) out vec4 gAlbedoSpec;
#ifndef GBUFFER_NO_EMISSIVE_AO
layout(location = 2) out vec4 gEmissiveAo;
#endif
#else
layout(location = 0) out vec4 gPosition;
layout(location = 1) out vec4 gNormal;
layout(location = 2) out vec4 gAlbedoSpec;
layout(location = 3) out vec4 gEmissiveAo;
#endif

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 positionDepth = texelFetch(uImportPositionDepth, px, 0);
    if (positionDepth.w >= 1.0) discard;  // background: the clear values stay
    gl_FragDepth = positionDepth.w;
#ifndef GBUFFER_POSITION_FROM_DEPTH
    gPosition = vec4(positionDepth.xyz, 1.0);
#endif
    gNormal = encodeNormal(normalize(texelFetch(uImportNormal, px, 0).xyz));
    gAlbedoSpec = texelFetch(uImportAlbedoSpec, px, 0);
#ifndef GBUFFER_NO_EMISSIVE_AO
    // As the geometry pass writes the material's: the layout's format keeps what it can (RGBA8
    // clamps to [0, 1] in 1/255 steps); a layout without the attachment (packed) keeps neither.
    gEmissiveAo = texelFetch(uImportEmissiveAo, px, 0);
#endif
}
