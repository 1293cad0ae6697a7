// The table of the renderer's programs.
#include "gl/program_id.h"

namespace gbl {

std::span<ProgramInfo const> programTable() {
    using G = ProgramGroup;
    static ProgramInfo const table[] = {
        {ProgramId::Geometry,
         G::Core,
         {"geometry", {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "geometry.frag"}}, {}}},
        {ProgramId::LightingQuad,
         G::Core,
         {"lighting_quad", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "lighting_quad.frag"}}, {}}},
        {ProgramId::Forward,
         G::Core,
         {"forward", {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "forward.frag"}}, {}}},
        {ProgramId::DepthCopy,
         G::Core,
         {"depth_copy", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "depth_copy.frag"}}, {}}},
        {ProgramId::LightCube,
         G::Core,
         {"light_cube", {{GL_VERTEX_SHADER, "light_cube.vert"}, {GL_FRAGMENT_SHADER, "light_cube.frag"}}, {}}},
        {ProgramId::View,
         G::Core,
         {"view", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "view.frag"}}, {}}},
        {ProgramId::CoverageAllLights,
         G::Core,
         {"coverage_all_lights",
          {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "coverage_all_lights.frag"}},
          {}}},
        {ProgramId::GBufferDecode,
         G::Core,
         {"gbuffer_decode", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "gbuffer_decode.frag"}}, {}}},
        {ProgramId::LightCombine,
         G::Core,
         {"light_combine", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "light_combine.frag"}}, {}}},
        {ProgramId::Import,
         G::Core,
         {"import", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "import.frag"}}, {}}},
        {ProgramId::TexelCopy,
         G::Core,
         {"texel_copy", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "texel_copy.frag"}}, {}}},
        {ProgramId::LightVolume,
         G::Volumes,
         {"light_volume", {{GL_VERTEX_SHADER, "light_volume.vert"}, {GL_FRAGMENT_SHADER, "light_volume.frag"}}, {}}},
        {ProgramId::LightVolumeCoverage,
         G::Volumes,
         {"light_volume_coverage",
          {{GL_VERTEX_SHADER, "light_volume.vert"}, {GL_FRAGMENT_SHADER, "light_volume.frag"}},
          {"COVERAGE"}}},
        {ProgramId::LightVolumeStencil,
         G::Volumes,
         {"light_volume_stencil",
          {{GL_VERTEX_SHADER, "light_volume.vert"}, {GL_FRAGMENT_SHADER, "light_volume_stencil.frag"}},
          {}}},
        {ProgramId::LightVolumeWire,
         G::Volumes,
         {"light_volume_wire",
          {{GL_VERTEX_SHADER, "light_volume.vert"}, {GL_FRAGMENT_SHADER, "light_volume_wire.frag"}},
          {}}},
        {ProgramId::LightingTiled, G::Tiled, {"lighting_tiled", {{GL_COMPUTE_SHADER, "lighting_tiled.comp"}}, {}}},
        {ProgramId::TileBin, G::Tiled, {"tile_bin", {{GL_COMPUTE_SHADER, "tile_bin.comp"}}, {}}},
        {ProgramId::TileDepth, G::Tiled, {"tile_depth", {{GL_COMPUTE_SHADER, "tile_depth.comp"}}, {}}},
        {ProgramId::ClusterBuild, G::Clustered, {"cluster_build", {{GL_COMPUTE_SHADER, "cluster_build.comp"}}, {}}},
        {ProgramId::ClusterBin, G::Clustered, {"cluster_bin", {{GL_COMPUTE_SHADER, "tile_bin.comp"}}, {}}},
        {ProgramId::ClusterShade, G::Clustered, {"cluster_shade", {{GL_COMPUTE_SHADER, "cluster_shade.comp"}}, {}}},
    };
    static_assert(std::size(table) == kProgramCount, "programTable(): one row per ProgramId, in enum order");
    return table;
}

}  // namespace gbl
