// Viewer tools of the view pass: colormaps for one shown channel and the NaN / Inf / negative /
// clipping overlays. Included by view.frag; the tables match ui/model/colormap.cpp.

// COLORMAP_* and OVERLAY_* come from view_constants.glsl (included first by view.frag).

uniform int uColormap;
uniform int uOverlays;

// 33 stops each, linearly interpolated (see ui/model/colormap.cpp for where they come from).
const vec3 kTurbo[33] = vec3[33](
    vec3(0.136, 0.091, 0.107), vec3(0.242, 0.164, 0.446), vec3(0.288, 0.244, 0.686), vec3(0.291, 0.328, 0.844),
    vec3(0.269, 0.415, 0.935), vec3(0.234, 0.501, 0.973), vec3(0.197, 0.586, 0.970), vec3(0.167, 0.666, 0.936),
    vec3(0.148, 0.740, 0.881), vec3(0.146, 0.808, 0.811), vec3(0.162, 0.866, 0.733), vec3(0.197, 0.915, 0.653),
    vec3(0.250, 0.953, 0.573), vec3(0.319, 0.979, 0.497), vec3(0.401, 0.993, 0.428), vec3(0.492, 0.994, 0.367),
    vec3(0.589, 0.982, 0.313), vec3(0.685, 0.958, 0.268), vec3(0.777, 0.921, 0.231), vec3(0.861, 0.873, 0.201),
    vec3(0.932, 0.814, 0.177), vec3(0.985, 0.746, 0.158), vec3(1.000, 0.670, 0.142), vec3(1.000, 0.588, 0.128),
    vec3(1.000, 0.502, 0.114), vec3(0.988, 0.415, 0.100), vec3(0.935, 0.329, 0.084), vec3(0.866, 0.248, 0.067),
    vec3(0.786, 0.175, 0.047), vec3(0.705, 0.114, 0.027), vec3(0.632, 0.070, 0.006), vec3(0.580, 0.047, 0.000),
    vec3(0.566, 0.050, 0.000));
const vec3 kViridis[33] = vec3[33](
    vec3(0.278, 0.005, 0.334), vec3(0.281, 0.049, 0.377), vec3(0.282, 0.093, 0.417), vec3(0.281, 0.135, 0.453),
    vec3(0.278, 0.176, 0.483), vec3(0.272, 0.215, 0.507), vec3(0.264, 0.253, 0.526), vec3(0.252, 0.288, 0.539),
    vec3(0.239, 0.322, 0.548), vec3(0.223, 0.355, 0.554), vec3(0.205, 0.387, 0.556), vec3(0.187, 0.418, 0.557),
    vec3(0.170, 0.448, 0.557), vec3(0.153, 0.478, 0.555), vec3(0.139, 0.507, 0.553), vec3(0.128, 0.537, 0.550),
    vec3(0.122, 0.566, 0.546), vec3(0.121, 0.595, 0.540), vec3(0.128, 0.624, 0.531), vec3(0.142, 0.653, 0.519),
    vec3(0.165, 0.681, 0.503), vec3(0.197, 0.709, 0.482), vec3(0.239, 0.736, 0.455), vec3(0.291, 0.761, 0.421),
    vec3(0.352, 0.785, 0.382), vec3(0.423, 0.807, 0.337), vec3(0.501, 0.827, 0.288), vec3(0.585, 0.845, 0.236),
    vec3(0.673, 0.861, 0.187), vec3(0.762, 0.875, 0.144), vec3(0.847, 0.886, 0.114), vec3(0.924, 0.897, 0.107),
    vec3(0.987, 0.906, 0.131));

vec3 applyColormap(int map, float t) {
    t = clamp(t, 0.0, 1.0);  // a NaN t is caught by the overlay, or shows whatever clamp gives
    if (map == COLORMAP_GREY) return vec3(t);
    float p = t * 32.0;
    int i = min(int(p), 31);
    if (map == COLORMAP_TURBO) return mix(kTurbo[i], kTurbo[i + 1], p - float(i));
    return mix(kViridis[i], kViridis[i + 1], p - float(i));
}

// From the bits, so that no compiler's fast-math folding can decide a NaN is never there.
bool bitsNaN(float x) {
    uint u = floatBitsToUint(x);
    return (u & 0x7f800000u) == 0x7f800000u && (u & 0x007fffffu) != 0u;
}
bool bitsInf(float x) { return (floatBitsToUint(x) & 0x7fffffffu) == 0x7f800000u; }

// The displayed colour after the tools: raw is the value as stored (before the range remap),
// shownValue after it, mask 1 for each shown channel. Overlays win over the colormap, in the
// order NaN, Inf, negative, clipping.
vec3 viewTools(vec4 raw, vec4 shownValue, vec4 mask, vec3 color) {
    bool oneChannel = dot(mask, vec4(1.0)) == 1.0;
    if (oneChannel && uColormap != COLORMAP_GREY) color = applyColormap(uColormap, dot(shownValue, mask));
    if (uOverlays == 0) return color;
    bool nan = false, inf = false, negative = false, below = false, above = false;
    for (int c = 0; c < 4; ++c) {
        if (mask[c] == 0.0) continue;
        bool n = bitsNaN(raw[c]), i = bitsInf(raw[c]);
        nan = nan || n;
        inf = inf || i;
        if (n) continue;
        negative = negative || raw[c] < 0.0;
        below = below || shownValue[c] < 0.0;
        above = above || shownValue[c] > 1.0;
    }
    if ((uOverlays & OVERLAY_NAN) != 0 && nan) return vec3(1.0, 0.0, 1.0);
    if ((uOverlays & OVERLAY_INF) != 0 && inf) return vec3(0.0, 1.0, 0.0);
    if ((uOverlays & OVERLAY_NEGATIVE) != 0 && negative) return vec3(0.0, 1.0, 1.0);
    if ((uOverlays & OVERLAY_CLIP) != 0 && below) return vec3(0.0, 0.0, 1.0);
    if ((uOverlays & OVERLAY_CLIP) != 0 && above) return vec3(1.0, 0.0, 0.0);
    return color;
}
