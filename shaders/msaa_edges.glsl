// The msaa edges strategy's detection (docs/msaa.md): a pixel is complex when any of its samples
// differs from sample 0 in coverage, position, normal or albedo beyond the thresholds of
// core/msaa.h (MsaaThresholds, set as uniforms).
#ifndef GBL_MSAA_EDGES_GLSL
#define GBL_MSAA_EDGES_GLSL
uniform float uMsaaRelativeDistance;  // off sample 0's plane by more than this share of the eye distance
uniform float uMsaaNormalCos;         // normals whose cosine is below this
uniform float uMsaaAlbedo;            // albedo or specular apart by more than this in a channel

bool msaaComplexPixel(ivec2 px) {
    gSample = 0;
    vec3 p0;
    bool drawn0 = gbufferPosition(px, p0);
    vec3 n0 = gbufferNormal(px);
    vec4 a0 = gbufferAlbedoSpec(px);
    float reach = uMsaaRelativeDistance * length(p0 - uViewPos);
    for (int i = 1; i < GBL_MSAA_SAMPLES; ++i) {
        gSample = i;
        vec3 p;
        bool drawn = gbufferPosition(px, p);
        if (drawn != drawn0) return true;
        if (!drawn) continue;
        // Off sample 0's tangent plane: another surface. Along the plane is the pixel's own extent,
        // which the layouts that rebuild each sample's position at its own place spread over.
        if (abs(dot(p - p0, n0)) > reach) return true;
        if (dot(gbufferNormal(px), n0) < uMsaaNormalCos) return true;
        vec4 d = abs(gbufferAlbedoSpec(px) - a0);
        if (max(max(d.r, d.g), max(d.b, d.a)) > uMsaaAlbedo) return true;
    }
    return false;
}
#endif
