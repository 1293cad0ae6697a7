// The renderer's GLSL programs by typed id, with the files each is built from and what a failed
// build costs: a core program is fatal, an optional one takes its lighting mode away.
#pragma once

#include "gl/gl_api.h"

#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace gbl {

enum class ProgramId {
    // core
    Geometry,
    LightingQuad,
    Forward,
    DepthCopy,
    LightCube,
    View,
    CoverageAllLights,
    GBufferDecode,
    LightCombine,    // accumulation split: the two light targets into the lit image
    Import,          // re-lighting: an imported G-buffer into the layout's targets
    TexelCopy,       // a texture into a float target, for read-backs WebGL2 cannot do directly
    GlassOutline,    // the blended surfaces hatched over a view
    GlassOverCubes,  // forward.frag tonemapped (FORWARD_TONEMAP): the blended surfaces over the light cubes
    // volumes mode
    LightVolume,
    LightVolumeCoverage,
    LightVolumeStencil,
    LightVolumeWire,
    // tiled mode
    LightingTiled,
    TileBin,    // the light binning pass before the tiled lists (shaders/tile_bin.comp)
    TileDepth,  // each tile's depth range, before either binning pass (clustered builds it too)
    // clustered mode
    ClusterBuild,
    ClusterBin,  // the same binning pass before the cluster lists
    ClusterShade,
    // forward+ mode (with the tiled group's TileDepth and TileBin)
    ForwardPlus,  // forward.frag reading its tile's list (FORWARD_TILE_LISTS)
    // prepass mode (deferred lighting)
    PrepassGeometry,  // the thin G-buffer: normal and specular exponent
    PrepassLight,     // every light into the diffuse and specular light targets
    PrepassShade,     // the second geometry pass: materials applied to the light
    // light_volume.frag reading the thin G-buffer (PREPASS_LIGHTS): prepass's light pass with volumes
    // (its mesh and stencil program are the volumes group's)
    PrepassLightVolume,
};
inline constexpr std::size_t kProgramCount = std::size_t(ProgramId::PrepassLightVolume) + 1;

// What needs the program: every frame (core), or one optional group that is built on first use.
enum class ProgramGroup { Core, Volumes, Tiled, Clustered, ForwardPlus, Prepass };

struct ProgramDesc {
    std::string name;                                    // e.g. "geometry", for logs and labels
    std::vector<std::pair<GLenum, std::string>> stages;  // stage and file name in shaders/
    std::vector<std::string> defines;                    // inserted after #version as "#define X"
};

struct ProgramInfo {
    ProgramId id;
    ProgramGroup group;
    ProgramDesc desc;
};

// Every program, in ProgramId order.
std::span<ProgramInfo const> programTable();
inline ProgramInfo const& programInfo(ProgramId id) {
    return programTable()[std::size_t(id)];
}

}  // namespace gbl
