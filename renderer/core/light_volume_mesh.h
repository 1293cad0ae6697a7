// The light-volume sphere: a position-only UV sphere and the scale that makes it enclose the
// true sphere of a light's radius (pure math, no GL; the renderer uploads it once).
#pragma once

#include <glm/glm.hpp>

#include <cmath>
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

// Distance from the eye to a corner of the near plane: the farthest a near-plane-clipped point
// can be from the eye. fovY in radians, aspect = width / height.
inline float nearPlaneCornerDistance(float fovY, float aspect, float nearPlane) {
    float const h = std::tan(fovY * 0.5f) * nearPlane, w = h * aspect;
    return std::sqrt(nearPlane * nearPlane + h * h + w * w);
}

// Whether the camera's near plane may cut into a light's volume (enclosing radius =
// radius * enclosingScale), so that the volume's front faces could be clipped away. The `flip`
// cull mode draws such a light's back faces instead of its front faces.
inline bool volumeMayContainCamera(glm::vec3 eye, glm::vec3 lightPosition, float enclosingRadius,
                                   float nearCornerDistance) {
    return glm::length(eye - lightPosition) < enclosingRadius + nearCornerDistance;
}

}  // namespace gbl
