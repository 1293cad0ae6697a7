// The light-volume sphere: a position-only UV sphere and the scale that makes it enclose the
// true sphere of a light's radius (pure math, no GL; the renderer uploads it once).
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace gbl {

// Tessellation used by the volumes pass and the wireframe overlay. Odd stacks put a band of
// quads across the equator, which makes the enclosing scale exactly
// 1 / (cos(pi / slices) * cos(pi / (2 * stacks))) (see enclosingScale below): 1.0301 here.
inline constexpr int kLightVolumeStacks = 11;
inline constexpr int kLightVolumeSlices = 16;

struct SphereMesh {
    int stacks = 0;
    int slices = 0;
    // Vertices on the unit sphere: the north pole (+Y), stacks - 1 rings of `slices` vertices
    // from north to south, the south pole.
    std::vector<glm::vec3> positions;
    // Triangle list, counter-clockwise seen from outside (so culling back faces keeps the
    // faces towards the camera). Each band quad is two triangles in one plane.
    std::vector<std::uint32_t> triangles;
    // Line list: every ring and every meridian edge once, for wireframes.
    std::vector<std::uint32_t> lines;
};

// stacks >= 2 bands from pole to pole, slices >= 3 around. Throws std::invalid_argument
// ("makeLightVolumeSphere(): ...") for smaller values.
SphereMesh makeLightVolumeSphere(int stacks = kLightVolumeStacks, int slices = kLightVolumeSlices);

// Smallest distance from the origin to the plane of any triangle (the inscribed radius of the
// convex mesh). Degenerate triangles are ignored.
float minFacePlaneDistance(std::span<glm::vec3 const> positions, std::span<std::uint32_t const> triangles);

// Factor to scale the unit-vertex mesh by so that it encloses the unit sphere: every face
// plane then lies at distance >= 1 from the centre, so a volume scaled by radius * this factor
// covers every pixel the light can reach. A polyhedron whose vertices lie on the sphere cuts
// into it between the vertices; the deepest cut is the face closest to the centre.
// Computed from the actual faces, so it holds for whatever tessellation is passed in.
float enclosingScale(SphereMesh const& mesh);

}  // namespace gbl
