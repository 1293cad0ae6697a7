// Texture and image units of every shader, one name per slot. The C++ side reads this very file
// (cmake/shader_bindings.cmake turns it into gl/shader_bindings.h), and the comment after each
// sampler slot names the sampler uniform the shader library points at that unit after linking.
// Slots may repeat across programs that never run together (material vs G-buffer), never within one.
#ifndef GBL_BINDINGS_GLSL
#define GBL_BINDINGS_GLSL
#define BIND_GBUFFER_POSITION 0     // sampler uPosition
#define BIND_GBUFFER_NORMAL 1       // sampler uNormal
#define BIND_GBUFFER_ALBEDO_SPEC 2  // sampler uAlbedoSpec
#define BIND_LIGHTS 3               // sampler uLights
#define BIND_VOLUME_INSTANCES 4     // sampler uInstances
#define BIND_DEPTH 5                // sampler uDepth
#define BIND_LIGHTING 6             // sampler uLighting
#define BIND_COVERAGE 7             // sampler uCoverage
#define BIND_MATERIAL_BASE_COLOR 0  // sampler uBaseColorTex
#define BIND_MATERIAL_NORMAL 1      // sampler uNormalTex
#define BIND_MATERIAL_SPECULAR 2    // sampler uSpecularTex
#define BIND_GBUFFER_EMISSIVE 8     // sampler uEmissiveAo
#define BIND_MATERIAL_EMISSIVE 9    // sampler uEmissiveTex
#define BIND_MATERIAL_OCCLUSION 10  // sampler uOcclusionTex
#define BIND_DIFFUSE_LIGHT 11       // sampler uDiffuseLight
#define BIND_SPECULAR_LIGHT 12      // sampler uSpecularLight
#define BIND_CLUSTER_LIST 13        // sampler uClusterList
#define BIND_PREPASS_NORMAL 14      // sampler uPrepassNormal
#define BIND_READBACK_SOURCE 0      // sampler uReadbackSource
#define BIND_IMPORT_POSITION_DEPTH 0  // sampler uImportPositionDepth
#define BIND_IMPORT_NORMAL 1          // sampler uImportNormal
#define BIND_IMPORT_ALBEDO_SPEC 2     // sampler uImportAlbedoSpec
#define BIND_IMPORT_EMISSIVE_AO 3     // sampler uImportEmissiveAo
// Image units of the tiled compute pass (declared with layout(binding = ...) in the shader).
#define BIND_IMAGE_LIGHTING 0
#define BIND_IMAGE_COVERAGE 1
#define BIND_IMAGE_SPECULAR_LIGHT 2  // accumulation split: the specular target (image 0 the diffuse one)
// Storage buffers of the clustered passes (cluster_build.comp writes, cluster_shade.comp reads).
#define BIND_SSBO_CLUSTER_COUNTS 0
#define BIND_SSBO_CLUSTER_LIGHTS 1
// Storage buffers of the light binning pass (tile_bin.comp writes, lighting_tiled.comp and
// cluster_build.comp read): each 16x16 tile's candidate lights.
#define BIND_SSBO_TILE_BIN_COUNTS 2
#define BIND_SSBO_TILE_BIN_LIGHTS 3
// Each tile's view-depth range (tile_depth.comp writes, tile_bin.comp reads).
#define BIND_SSBO_TILE_DEPTH 4
// The shader-checks build's report of out-of-range accesses (shader_checks.glsl).
#define BIND_SSBO_SHADER_CHECKS 5
#endif
