// Clustered lighting, step 1 (OpenGL 4.3): one invocation per cluster (a 16x16-pixel tile cut
// into exponential depth slices) lists, in index order, the lights whose sphere reaches the
// cluster's view-space box (renderer/core/cluster_math.h does the same on the CPU).
#version 430 core
#include "bindings.glsl"
#include "lighting.glsl"
#include "light_fetch.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = BIND_SSBO_CLUSTER_COUNTS) writeonly buffer ClusterCounts { uint clusterCount[]; };
layout(std430, binding = BIND_SSBO_CLUSTER_LIGHTS) writeonly buffer ClusterLights { uint clusterLight[]; };

uniform int uLightCount;
uniform mat4 uView;
uniform mat4 uInverseProjection;
uniform ivec2 uScreenSize;
uniform ivec3 uGrid;  // tiles x, tiles y, slices
uniform int uTileSize;
uniform int uMaxLights;  // list entries per cluster (kClusterMaxLights)
uniform float uNear;
uniform float uFar;

// One batch of lights in view space (xyz, radius), loaded once per work group instead of once
// per cluster: every cluster tests every light, so this divides the fetches by 64.
shared vec4 sLights[64];

float sliceNear(int slice) { return uNear * pow(uFar / uNear, float(slice) / float(uGrid.z)); }

void main() {
    int id = int(gl_GlobalInvocationID.x);
    int local = int(gl_LocalInvocationIndex);
    bool valid = id < uGrid.x * uGrid.y * uGrid.z;
    int tx = id % uGrid.x, ty = (id / uGrid.x) % uGrid.y, slice = id / (uGrid.x * uGrid.y);

    // The box around the tile's four corner rays between the slice's depths.
    ivec2 lo = ivec2(tx, ty) * uTileSize, hi = min(lo + uTileSize, uScreenSize);
    float d0 = sliceNear(slice), d1 = sliceNear(slice + 1);
    vec3 boxLo = vec3(3.0e38), boxHi = vec3(-3.0e38);
    for (int corner = 0; corner < 4; ++corner) {
        vec2 pxy = vec2((corner & 1) != 0 ? hi.x : lo.x, (corner & 2) != 0 ? hi.y : lo.y);
        vec4 v = uInverseProjection * vec4(pxy / vec2(uScreenSize) * 2.0 - 1.0, 1.0, 1.0);
        vec3 ray = v.xyz / v.w;
        ray /= -ray.z;  // the point at view depth 1
        boxLo = min(boxLo, min(ray * d0, ray * d1));
        boxHi = max(boxHi, max(ray * d0, ray * d1));
    }

    uint count = 0u;
    uint base = uint(id) * uint(uMaxLights);
    for (int start = 0; start < uLightCount; start += 64) {
        int i = start + local;
        vec4 light = vec4(0.0, 0.0, 0.0, -1.0);
        if (i < uLightCount) {
            vec4 pr = texelFetch(uLights, i * 4);
            light = vec4((uView * vec4(pr.xyz, 1.0)).xyz, pr.w);
        }
        sLights[local] = light;
        memoryBarrierShared();
        barrier();
        if (valid) {
            int n = min(64, uLightCount - start);
            for (int k = 0; k < n; ++k) {
                vec4 l = sLights[k];
                // A hair larger than the radius: a pixel on a slice boundary, put in the
                // neighbouring slice by rounding, still finds every light that reaches it.
                float r = l.w * 1.0001 + 1e-4;
                vec3 d = l.xyz - clamp(l.xyz, boxLo, boxHi);
                if (l.w > 0.0 && dot(d, d) <= r * r) {
                    if (count < uint(uMaxLights)) clusterLight[base + count] = uint(start + k);
                    ++count;  // the true count, also past the cap (cluster_shade.comp then loops over all)
                }
            }
        }
        barrier();
    }
    if (valid) clusterCount[id] = count;
}
