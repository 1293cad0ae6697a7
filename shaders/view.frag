// Turns one frame image into displayable colour: the tonemapped final image or a debug view
// of any attachment, with channel isolation and range remapping (the texture viewers use it too).
#version 330 core
#include "bindings.glsl"

#include "view_constants.glsl"
#include "gbuffer_read.glsl"
#include "tonemap.glsl"

uniform sampler2D uLighting;
uniform sampler2D uCoverage;
uniform sampler2D uDiffuseLight;   // accumulation split's targets
uniform sampler2D uSpecularLight;

uniform int uView;
// A program built for one view (ShaderLibrary::variant, "VIEW_ONLY n") switches on a constant: the
// compiler keeps that view's code alone. Rasterisers that run every branch under a mask (llvmpipe,
// SwiftShader) would otherwise run all of the views' code at every pixel.
#ifdef VIEW_ONLY
#define SHOWN_VIEW VIEW_ONLY
#else
#define SHOWN_VIEW uView
#endif
uniform vec4 uChannelMask;   // 1 for each shown channel
uniform float uRangeMin;
uniform float uRangeMax;
uniform int uNormalDisplay;
uniform float uNear;
uniform float uFar;
uniform int uClusterSlices;  // kClusterSlices: the clustered grid's exponential depth slices
// 1: a prepass frame (docs/deferred_lighting.md). Its G-buffer is the thin one: uPrepassNormal
// (world normal xyz, specular exponent w) and uDepth, which is then the lit depth it drew. It keeps
// no albedo, emission or occlusion (its second geometry pass reads them from the materials).
uniform int uThinGBuffer;
uniform sampler2D uPrepassNormal;

in vec2 vUV;
out vec4 fragColor;

#include "view_tools.glsl"

#include "depth.glsl"

vec4 remap(vec4 v) { return (v - vec4(uRangeMin)) / max(uRangeMax - uRangeMin, 1e-20); }

// The bin of a count on the heat maps' one scale (core/heat_scale.h heatBin is the twin): bin k
// holds HEAT_EDGES[k] up to the next edge; NaN and negative counts fall in bin 0.
int heatBin(float count) {
    int bin = 0;
    for (int k = 1; k < HEAT_BINS; ++k)
        if (count >= float(HEAT_EDGES[k])) bin = k;
    return bin;
}

vec3 heatColor(float count) { return HEAT_COLORS[heatBin(count)] / 255.0; }

// Legend along the bottom edge (frames of at least 64x64): one swatch per bin, equal widths
// (HEAT_SWATCH texels, fewer on narrow frames), bin 0 on the left; the viewport labels them. For
// the heat map the lower half shows each colour as dimmed where none of the evaluated lights lit
// the surface (HEAT_WASTED_DIM).
vec3 heatLegend(ivec2 px, vec3 color) {
    ivec2 size = textureSize(uCoverage, 0);
    if (size.x < 64 || size.y < 64) return color;
    int w = max(min(size.x - 16, HEAT_SWATCH * HEAT_BINS) / HEAT_BINS, 1);
    int x0 = 8, x1 = x0 + w * HEAT_BINS, y0 = 6, y1 = 22;
    if (px.x < x0 - 1 || px.x > x1 || px.y < y0 - 1 || px.y > y1) return color;
    if (px.x == x0 - 1 || px.x == x1 || px.y == y0 - 1 || px.y == y1) return vec3(1.0);  // frame
    vec3 swatch = HEAT_COLORS[(px.x - x0) / w] / 255.0;
    if (SHOWN_VIEW == VIEW_HEATMAP && px.y < (y0 + y1) / 2) swatch *= HEAT_WASTED_DIM;
    return swatch;
}

// The depth-slice view's colour of slice k (core/cluster_math.h, clusterSliceColor, is the twin):
// hues a golden-ratio turn apart, every other slice darker, so neighbouring slices always differ.
vec3 sliceColor(int slice) {
    float h = fract(float(slice) * 0.618034);
    vec3 k = clamp(abs(fract(vec3(h) + vec3(1.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0) - 1.0, 0.0, 1.0);
    return ((slice % 2) == 0 ? 1.0 : 0.6) * mix(vec3(1.0), k, 0.75);
}

// The slice of view depth z, as cluster_shade.comp files a pixel (clusterSlice on the CPU).
int depthSlice(float z) {
    if (!(z > uNear)) return 0;
    return clamp(int(floor(log(z / uNear) / log(uFar / uNear) * float(uClusterSlices))), 0, uClusterSlices - 1);
}

// Slice legend along the bottom edge (frames of at least 64x64): one swatch per slice, slice 0
// (nearest) on the left, SLICE_SWATCH texels each (fewer on narrow frames). The viewport labels
// the swatches with their view-depth ranges.
vec3 sliceLegend(ivec2 px, vec3 color) {
    ivec2 size = textureSize(uDepth, 0);
    if (size.x < 64 || size.y < 64) return color;
    int w = max(min(size.x - 16, SLICE_SWATCH * uClusterSlices) / uClusterSlices, 1);
    int x0 = 8, x1 = x0 + w * uClusterSlices, y0 = 6, y1 = 22;
    if (px.x < x0 - 1 || px.x > x1 || px.y < y0 - 1 || px.y > y1) return color;
    if (px.x == x0 - 1 || px.x == x1 || px.y == y0 - 1 || px.y == y1) return vec3(1.0);  // frame
    return sliceColor((px.x - x0) / w);
}

// The thin G-buffer's surface at px: false where nothing was drawn; the position rebuilt from the
// depth as prepass_light.frag rebuilds it.
bool thinPosition(ivec2 px, out vec3 position) {
    float d = texelFetch(uDepth, px, 0).r;
    vec2 ndc = (vec2(px) + 0.5) / vec2(textureSize(uDepth, 0)) * 2.0 - 1.0;
    vec4 world = uInverseViewProj * vec4(ndc, d * 2.0 - 1.0, 1.0);
    position = world.xyz / world.w;
    return d < 1.0;
}

bool surfacePosition(ivec2 px, out vec3 position) {
    return uThinGBuffer != 0 ? thinPosition(px, position) : gbufferPosition(px, position);
}

// What the layout's views show of the thin G-buffer: its normal, its exponent in the specular
// view, its one colour target as raw0; zero for what it does not store.
vec4 thinView(ivec2 px, int view) {
    vec3 p;
    bool drawn = thinPosition(px, p);
    vec4 stored = texelFetch(uPrepassNormal, px, 0);
    if (view == VIEW_NORMAL) return drawn ? vec4(stored.xyz, 1.0) : vec4(0.0);
    if (view == VIEW_SPECULAR) return vec4(stored.www, 1.0);
    if (view == VIEW_RAW0) return stored;
    return vec4(0.0);
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 v;
    bool data = true;  // data views are remapped; the final image and heat maps are not
    switch (SHOWN_VIEW) {
    case VIEW_FINAL: v = vec4(tonemap(texelFetch(uLighting, px, 0).rgb), 1.0); data = false; break;
    case VIEW_LIGHTING: v = texelFetch(uLighting, px, 0); break;
    // Position and normal decoded as the lighting reads them, so every layout shows the same quantity.
    case VIEW_POSITION: {
        vec3 p;
        bool drawn = surfacePosition(px, p);
        v = drawn ? vec4(p, 1.0) : vec4(0.0);
        break;
    }
    case VIEW_NORMAL: {
        vec3 p;
        vec4 n = uThinGBuffer != 0 ? thinView(px, VIEW_NORMAL)
                 : gbufferPosition(px, p) ? vec4(gbufferNormal(px), 1.0) : vec4(0.0);
        v = vec4(uNormalDisplay == NORMALS_ABSOLUTE ? abs(n.xyz) : n.xyz * 0.5 + 0.5, n.w);
        data = false;
        break;
    }
    case VIEW_RAW0: v = uThinGBuffer != 0 ? thinView(px, VIEW_RAW0) : gbufferRawAttachment(px, 0); break;
    case VIEW_RAW1: v = uThinGBuffer != 0 ? thinView(px, VIEW_RAW1) : gbufferRawAttachment(px, 1); break;
    case VIEW_RAW2: v = uThinGBuffer != 0 ? thinView(px, VIEW_RAW2) : gbufferRawAttachment(px, 2); break;
    case VIEW_RAW3: v = uThinGBuffer != 0 ? thinView(px, VIEW_RAW3) : gbufferRawAttachment(px, 3); break;
    case VIEW_EMISSIVE: v = uThinGBuffer != 0 ? thinView(px, VIEW_EMISSIVE) : vec4(gbufferEmissiveAo(px).rgb, 1.0); break;
    case VIEW_OCCLUSION: v = uThinGBuffer != 0 ? thinView(px, VIEW_OCCLUSION) : vec4(gbufferEmissiveAo(px).aaa, 1.0); break;
    case VIEW_DIFFUSE_LIGHT: v = texelFetch(uDiffuseLight, px, 0); break;
    case VIEW_SPECULAR_LIGHT: v = texelFetch(uSpecularLight, px, 0); break;
    case VIEW_ALBEDO: v = uThinGBuffer != 0 ? thinView(px, VIEW_ALBEDO) : texelFetch(uAlbedoSpec, px, 0); break;
    case VIEW_SPECULAR: v = uThinGBuffer != 0 ? thinView(px, VIEW_SPECULAR) : vec4(texelFetch(uAlbedoSpec, px, 0).aaa, 1.0); break;
    case VIEW_DEPTH: v = vec4(vec3(texelFetch(uDepth, px, 0).r), 1.0); break;
    case VIEW_DEPTH_LINEAR: v = vec4(vec3(linearDepth(texelFetch(uDepth, px, 0).r, uNear, uFar)), 1.0); break;
    case VIEW_HEATMAP: {
        // Colour: the bin of how many lights were evaluated here (volumes covering, tile or
        // cluster list, or all); brightness: the share of them that actually lit the surface.
        // Dim = wasted work (heatMapColor in core/heat_scale.h is the twin).
        vec2 c = texelFetch(uCoverage, px, 0).xy;  // x: evaluated, y: lit
        float share = c.x > 0.0 ? clamp(c.y / c.x, 0.0, 1.0) : 0.0;
        v = vec4(heatColor(c.x) * mix(HEAT_WASTED_DIM, 1.0, share), 1.0);
        data = false;
        break;
    }
    case VIEW_TILE_LIGHTS: {
        // Lights in each 16x16 tile's list, with the tile grid drawn dark.
        v = vec4(heatColor(texelFetch(uCoverage, px, 0).x), 1.0);
        if (px.x % 16 == 0 || px.y % 16 == 0) v.rgb *= 0.5;
        data = false;
        break;
    }
    case VIEW_CLUSTER_SLICES: {
        // Each surface's exponential depth slice (background black), from the depth buffer's view depth.
        float d = texelFetch(uDepth, px, 0).r;
        v = d < 1.0 ? vec4(sliceColor(depthSlice(linearDepth(d, uNear, uFar))), 1.0) : vec4(0.0, 0.0, 0.0, 1.0);
        v.rgb = sliceLegend(px, v.rgb);
        data = false;
        break;
    }
    default: v = vec4(1.0, 0.0, 1.0, 1.0); data = false; break;  // magenta: an unknown view
    }
    if (SHOWN_VIEW == VIEW_HEATMAP || SHOWN_VIEW == VIEW_TILE_LIGHTS) v.rgb = heatLegend(px, v.rgb);
    vec4 raw = v;  // as stored, for the NaN/Inf/negative overlays
    if (data) v = remap(v);
    // Channel isolation: one channel alone is shown as grey (so alpha/specular stays visible).
    float shown = dot(uChannelMask, vec4(1.0));
    if (shown == 1.0) {
        float g = dot(v, uChannelMask);
        fragColor = vec4(vec3(g), 1.0);
    } else {
        fragColor = vec4(v.rgb * uChannelMask.rgb, 1.0);
    }
    if (SHOWN_VIEW != VIEW_FINAL) fragColor.rgb = viewTools(raw, v, uChannelMask, fragColor.rgb);
}
