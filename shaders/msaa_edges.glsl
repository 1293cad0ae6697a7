// The msaa edges strategy's detection (docs/msaa.md): a pixel is complex when any of its samples
// differs from sample 0 in coverage, position, normal or albedo beyond the thresholds of
// core/msaa.h (MsaaThresholds, set as uniforms). The editor's samples-that-differ count
// (msaaDistinctSurfaces) asks the same question of every pair it compares; core/msaa_samples.h is
// the CPU twin of both.
#ifndef GBL_MSAA_EDGES_GLSL
#define GBL_MSAA_EDGES_GLSL
uniform float uMsaaRelativeDistance;  // off sample 0's plane by more than this share of the eye distance
uniform float uMsaaNormalCos;         // normals whose cosine is below this
uniform float uMsaaAlbedo;            // albedo or specular apart by more than this in a channel

// One sample's surface as the layout decodes it (gbuffer_read.glsl).
struct MsaaSurface {
    bool drawn;
    vec3 position;
    vec3 normal;
    vec4 albedoSpec;
};

MsaaSurface msaaSurface(ivec2 px, int sample) {
    gSample = sample;
    MsaaSurface s;
    s.drawn = gbufferPosition(px, s.position);
    s.normal = gbufferNormal(px);
    s.albedoSpec = gbufferAlbedoSpec(px);
    return s;
}

// Whether b holds the same surface as a (a plays sample 0): both background, or both drawn with
// b near a's tangent plane and normals and albedo within the thresholds. Along the plane is the
// pixel's own extent, which the layouts that rebuild each sample's position at its own place spread over.
bool msaaSameSurface(MsaaSurface a, MsaaSurface b) {
    if (a.drawn != b.drawn) return false;
    if (!a.drawn) return true;
    float reach = uMsaaRelativeDistance * length(a.position - uViewPos);
    if (abs(dot(b.position - a.position, a.normal)) > reach) return false;
    if (dot(b.normal, a.normal) < uMsaaNormalCos) return false;
    vec4 d = abs(b.albedoSpec - a.albedoSpec);
    return max(max(d.r, d.g), max(d.b, d.a)) <= uMsaaAlbedo;
}

bool msaaComplexPixel(ivec2 px) {
    MsaaSurface s0 = msaaSurface(px, 0);
    for (int i = 1; i < GBL_MSAA_SAMPLES; ++i)
        if (!msaaSameSurface(s0, msaaSurface(px, i))) return true;
    return false;
}

// How many distinct surfaces the pixel's samples hold, 1..GBL_MSAA_SAMPLES: a sample that matches
// no earlier sample that started a surface starts one. 1 exactly where msaaComplexPixel is false.
// Every loop bound is the constant sample count, so the compiler unrolls them and indexes the
// arrays with constants (a bound that grows with the count made this pass 2x slower on llvmpipe).
int msaaDistinctSurfaces(ivec2 px) {
    MsaaSurface s[GBL_MSAA_SAMPLES];
    bool first[GBL_MSAA_SAMPLES];
    int count = 0;
    for (int i = 0; i < GBL_MSAA_SAMPLES; ++i) {
        s[i] = msaaSurface(px, i);
        first[i] = true;
        for (int j = 0; j < i; ++j)
            if (first[j] && msaaSameSurface(s[j], s[i])) first[i] = false;
        if (first[i]) ++count;
    }
    return count;
}
#endif
