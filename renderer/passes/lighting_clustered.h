// Clustered lighting: light lists per froxel built on the GPU, then shading from them (OpenGL 4.3), see
// shaders/cluster_*.comp.
#pragma once

#include "core/cluster_math.h"
#include "gl/buffer.h"
#include "passes/shading_inputs.h"
#include "passes/tile_bins.h"

namespace gbl {

// The per-cluster light lists, kept between frames and regrown when the grid grows.
struct ClusterLists {
    gl::Buffer counts;  // uint per cluster: lights reaching it (also past the cap)
    gl::Buffer lights;  // `cap` uint light indices per cluster, ascending
    gl::Texture list;   // `lights` as an R32UI buffer texture: what cluster_shade.comp reads
    int clusters = 0;
    int cap = 0;  // clusterListCap() for this grid and context
};

struct LightingClusteredInput {
    DeferredInputs deferred;
    gl::Program const& build;  // ProgramId::ClusterBuild
    TileBinPrograms bin;       // ProgramId::TileDepth and ClusterBin: fill `bins` before the build
    TileBins& bins;
    gl::Program const& shade;  // ProgramId::ClusterShade
    ClusterLists& lists;
    gl::Texture const& hdr;       // RGBA16F image written when config.shade
    gl::Texture const& specular;  // RGBA16F: specular light, written when config.shade in split frames
    gl::Texture const& coverage;  // RG32F image written when config.coverage
    GlCaps const& caps;           // storage-block and buffer-texture limits that cap the lists
};
struct LightingClusteredConfig {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    int width = 0;
    int height = 0;
    float nearPlane = 0.1f;
    float farPlane = 100.0f;
    bool shade = true;      // write the lit image
    bool coverage = false;  // write x = lights in the pixel's cluster, y = lights that lit the pixel
};

// Builds the lists (first dispatch) and shades from them (second); the two are one pass for
// timing unless the caller brackets clusterListsPass on its own.
void clusterListsPass(LightingClusteredInput const& in, LightingClusteredConfig const& config);
LightingOutput clusterShadePass(LightingClusteredInput const& in, LightingClusteredConfig const& config);

}  // namespace gbl
