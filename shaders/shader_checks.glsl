// Range checks of the compute shaders' buffer, image and shared-array accesses (the shader-checks
// build, renderer/gl/shader_checks.h). CHECKED(site, index, size) is the index itself in an
// ordinary build. With GBL_SHADER_CHECKS defined, an index outside [0, size) is recorded in the
// ShaderChecks buffer (the first failure's program, site, index and size; every failure counted)
// and clamped into range, so the access that would have gone astray stays in bounds and the
// renderer reports it after the frame, like a GL error. Compute shaders only: GLSL 3.30 fragment
// shaders have no storage buffers, and they write nothing but their framebuffer; there CHECKED is the
// index itself in every build.
//
// Sites: one number per checked access, named in the renderer's report. The C++ side reads the
// `#define CHECK_SITE_...` lines of this very file, so a new site needs no second list.
#ifndef GBL_SHADER_CHECKS_GLSL
#define GBL_SHADER_CHECKS_GLSL
#define CHECK_SITE_TILE_DEPTH 1         // tileDepth[] (tile_depth_buffer.glsl)
#define CHECK_SITE_TILE_BIN_COUNT 2     // tileBinCount[]
#define CHECK_SITE_TILE_BIN_LIGHT 3     // tileBinLight[]
#define CHECK_SITE_KEPT 4               // sKept[] (tile_bin_read.glsl)
#define CHECK_SITE_SORTED 5             // sSorted4[] (tile_bin_read.glsl)
#define CHECK_SITE_LIGHT_MASK 6         // sLightMask[]
#define CHECK_SITE_LIGHT_WORDS 7        // sWords[]
#define CHECK_SITE_LIGHT_TEXEL 8        // uLights texels (light_fetch.glsl)
#define CHECK_SITE_CLUSTER_COUNT 9      // clusterCount[]
#define CHECK_SITE_CLUSTER_LIGHT 10     // clusterLight[]
#define CHECK_SITE_IMAGE 11             // imageStore coordinates

#if defined(GBL_SHADER_CHECKS) && __VERSION__ >= 430
layout(std430, binding = BIND_SSBO_SHADER_CHECKS) buffer ShaderChecks {
    uint checkFailures;  // every out-of-range access of the frame
    uint checkProgram;   // the first one's program (GBL_PROGRAM_ID, gl/program_id.h's order)
    uint checkSite;      // ... its CHECK_SITE_ number
    int checkIndex;      // ... the index it asked for
    int checkSize;       // ... and the size it had to stay below
};

int checkedIndex(int site, int index, int size) {
    if (index >= 0 && index < size) return index;
    if (atomicAdd(checkFailures, 1u) == 0u) {
        checkProgram = uint(GBL_PROGRAM_ID);
        checkSite = uint(site);
        checkIndex = index;
        checkSize = size;
    }
    return clamp(index, 0, max(size - 1, 0));
}
#define CHECKED(site, index, size) checkedIndex(site, int(index), int(size))
// An image coordinate inside the image: recorded as the flat index against the pixel count.
ivec2 checkedPixel(ivec2 px, ivec2 size) {
    bool inside = all(greaterThanEqual(px, ivec2(0))) && all(lessThan(px, size));
    if (inside) return px;
    checkedIndex(CHECK_SITE_IMAGE, px.y * size.x + px.x, size.x * size.y);
    return clamp(px, ivec2(0), max(size - 1, ivec2(0)));
}
#define CHECKED_PIXEL(px, size) checkedPixel(px, size)
#else
#define CHECKED(site, index, size) (index)
#define CHECKED_PIXEL(px, size) (px)
#endif
#endif
