// Light binning: each tile's depth range of drawn pixels (shaders/tile_depth.comp), then each
// light's index appended to the candidate lists of the 16x16 tiles its bounding sphere can cover
// within those ranges (shaders/tile_bin.comp), read by the tiled and clustered list passes.
#pragma once

#include "core/tile_math.h"
#include "gl/buffer.h"
#include "gl/program.h"
#include "gpu/light_buffer.h"

#include <glm/glm.hpp>

namespace gbl {

// The per-tile candidate lists, kept between frames and regrown when the grid grows.
struct TileBins {
    gl::Buffer counts;  // uint per tile: candidates (also past the cap)
    gl::Buffer lights;  // `cap` uint light indices per tile, in no particular order
    gl::Buffer depth;   // vec2 per tile: nearest and farthest view depth of its drawn pixels
    // forward+ with blended surfaces: each tile's lists again, binned from the near plane to its
    // farthest drawn pixel (TileBinConfig::blendedLists); the same cap.
    gl::Buffer blendedCounts;
    gl::Buffer blendedLights;
    int tiles = 0;
    int cap = 0;  // tileBinCap() for this grid and context
};

// The two programs of the pass.
struct TileBinPrograms {
    gl::Program const& depth;  // ProgramId::TileDepth
    gl::Program const& bin;    // ProgramId::TileBin or ProgramId::ClusterBin
};

struct TileBinInput {
    TileBinPrograms programs;
    LightBuffer const& lights;
    gl::Texture const& depth;  // the G-buffer's depth
    TileBins& bins;
    GlCaps const& caps;  // the storage-block limit that caps each tile's list
};
struct TileBinConfig {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    int width = 0;
    int height = 0;
    float nearPlane = 0.1f;
    float farPlane = 100.0f;
    bool blendedLists = false;  // also fill TileBins::blended* (forward+ frames with blended surfaces)
};

// Fills the bins and leaves them bound on BIND_SSBO_TILE_BIN_* for the list pass that follows.
void tileBinPass(TileBinInput const& in, TileBinConfig const& config);

}  // namespace gbl
