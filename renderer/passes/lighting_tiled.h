// Tiled lighting: a compute pass over 16x16 tiles (OpenGL 4.3), see shaders/lighting_tiled.comp.
#pragma once

#include "passes/shading_inputs.h"
#include "passes/tile_bins.h"

namespace gbl {

struct LightingTiledInput {
    DeferredInputs deferred;
    gl::Program const& program;  // ProgramId::LightingTiled
    TileBinPrograms bin;         // ProgramId::TileDepth and TileBin: fill `bins` first
    TileBins& bins;
    gl::Texture const& hdr;       // RGBA16F image written when config.shade
    gl::Texture const& specular;  // RGBA16F: specular light, written when config.shade in split frames
    gl::Texture const& coverage;  // RG32F image written when config.coverage
    GlCaps const& caps;           // the storage-block limit (tileBinPass)
};
struct LightingTiledConfig {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    int width = 0;
    int height = 0;
    float nearPlane = 0.1f;
    float farPlane = 100.0f;
    bool shade = true;      // write the lit image
    bool coverage = false;  // write x = lights in the tile, y = lights that lit the pixel
    bool binned = false;    // `bins` already hold this frame's candidates (tileBinPass ran)
};

LightingOutput lightingTiledPass(LightingTiledInput const& in, LightingTiledConfig const& config);

}  // namespace gbl
