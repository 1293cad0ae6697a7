// The enum values view.frag switches on. Each list matches a C++ enum one-to-one; the
// shader_constants_test reads this file and checks it against kDebugViewNames, kTonemapNames,
// NormalDisplay, kColormapNames and the kOverlay* bits, so a value added on one side only fails the build's tests.

// gbl::DebugView (core/pipeline_settings.h), VIEW_ + the upper-cased kDebugViewNames entry.
#define VIEW_FINAL 0
#define VIEW_LIGHTING 1
#define VIEW_POSITION 2
#define VIEW_NORMAL 3
#define VIEW_ALBEDO 4
#define VIEW_SPECULAR 5
#define VIEW_DEPTH 6
#define VIEW_DEPTH_LINEAR 7
#define VIEW_HEATMAP 8
#define VIEW_TILE_LIGHTS 9
#define VIEW_RAW0 10
#define VIEW_RAW1 11
#define VIEW_RAW2 12
#define VIEW_RAW3 13
#define VIEW_EMISSIVE 14
#define VIEW_OCCLUSION 15
#define VIEW_DIFFUSE_LIGHT 16
#define VIEW_SPECULAR_LIGHT 17
#define VIEW_CLUSTER_SLICES 18
// Width in texels of each slice's swatch in the depth-slice legend (kSliceSwatchTexels).
#define SLICE_SWATCH 12

// The count heat maps' one scale (core/heat_scale.h): bin k holds counts from HEAT_EDGES[k] up to
// the next edge, shown in HEAT_COLORS[k] (sRGB bytes); legend swatches HEAT_SWATCH texels wide.
#define HEAT_BINS 8
#define HEAT_SWATCH 32
const int HEAT_EDGES[HEAT_BINS] = int[HEAT_BINS](0, 1, 2, 4, 8, 16, 32, 64);
const vec3 HEAT_COLORS[HEAT_BINS] = vec3[HEAT_BINS](vec3(0, 0, 0), vec3(40, 60, 220), vec3(0, 160, 255),
    vec3(0, 200, 140), vec3(120, 220, 30), vec3(250, 220, 0), vec3(255, 120, 0), vec3(230, 0, 180));
// The heat map's brightness where none of the evaluated lights lit the surface (kHeatWastedDim).
const float HEAT_WASTED_DIM = 0.3;

// gbl::Tonemap, TONEMAP_ + the upper-cased kTonemapNames entry.
#define TONEMAP_EXPOSURE 0
#define TONEMAP_REINHARD 1
#define TONEMAP_CLAMP 2

// gbl::NormalDisplay (core/view_params.h).
#define NORMALS_BIASED 0
#define NORMALS_ABSOLUTE 1

// gbl::Colormap (core/view_params.h), COLORMAP_ + the upper-cased kColormapNames entry.
#define COLORMAP_GREY 0
#define COLORMAP_TURBO 1
#define COLORMAP_VIRIDIS 2

// gbl::kOverlay* bits (core/view_params.h).
#define OVERLAY_NAN 1
#define OVERLAY_INF 2
#define OVERLAY_NEGATIVE 4
#define OVERLAY_CLIP 8
