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
