// The enum values view.frag switches on. Each list matches a C++ enum one-to-one; the
// shader_constants_test reads this file and checks it against kDebugViewNames, kTonemapNames
// and NormalDisplay, so a value added on one side only fails the build's tests.

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

// gbl::Tonemap, TONEMAP_ + the upper-cased kTonemapNames entry.
#define TONEMAP_EXPOSURE 0
#define TONEMAP_REINHARD 1
#define TONEMAP_CLAMP 2

// gbl::NormalDisplay (core/view_params.h).
#define NORMALS_BIASED 0
#define NORMALS_ABSOLUTE 1
