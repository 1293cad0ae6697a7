// Geometry pass: writes the surface into the G-buffer in the current layout's encoding
// (core/gbuffer_layout.h: world position unless rebuilt from depth, the normal, albedo/specular,
// emissive/occlusion where the layout has room for them).
#version 330 core
#include "bindings.glsl"
#include "material.glsl"
#include "gbuffer_encoding.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUV;
in vec4 vTangent;

#ifdef GBUFFER_POSITION_FROM_DEPTH
layout(location = 0) out vec4 gNormal;      // encodeNormal(world normal)
layout(location = 1) out vec4 gAlbedoSpec;  // rgb linear albedo, a = specular intensity
#ifndef GBUFFER_NO_EMISSIVE_AO
layout(location = 2) out vec4 gEmissiveAo;  // rgb emitted radiance, a = ambient occlusion
#endif
#else
layout(location = 0) out vec4 gPosition;    // xyz world position, w = 1 where geometry was drawn
layout(location = 1) out vec4 gNormal;      // encodeNormal(world normal): xyz unit normal, w = 1
layout(location = 2) out vec4 gAlbedoSpec;  // rgb linear albedo, a = specular intensity
layout(location = 3) out vec4 gEmissiveAo;  // rgb emitted radiance, a = ambient occlusion
#endif

void main() {
    vec4 base = materialBaseColor(vUV);
    if (uAlphaMask && base.a < uAlphaCutoff) discard;  // alpha-mask materials are cut-outs
#ifndef GBUFFER_POSITION_FROM_DEPTH
    gPosition = vec4(vWorldPos, 1.0);
#endif
    gNormal = encodeNormal(materialNormal(vNormal, vTangent, vUV, gl_FrontFacing));
    gAlbedoSpec = vec4(base.rgb, materialSpecular(vUV));
#ifndef GBUFFER_NO_EMISSIVE_AO
    gEmissiveAo = vec4(materialEmissive(vUV), materialOcclusion(vUV));
#endif
}
