// The light-volume cone of spot lights: a position-only unit cone, the radial scale that makes it
// enclose the true cone, where it lands in the world for a light, and whether it may hold the
// camera (pure math, no GL; shaders/light_volume.vert places it the same way).
#pragma once

#include "core/point_light.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace gbl {

// Slices around the cone's base (the same count as the sphere's).
inline constexpr int kConeVolumeSlices = 16;
// Spots whose outer angle is wider than this are drawn with the sphere instead: the cone's base
// grows with tan(outer) (at 60 degrees it is 1.73 radii across each way, at 89 degrees 57) while
// the sphere never exceeds one radius, so past this the sphere covers fewer pixels.
inline constexpr float kConeVolumeMaxOuterDeg = 60.0f;

struct ConeMesh {
    int slices = 0;
    // Vertex 0: the apex at the origin; 1..slices: the base ring at z = 1, radius 1; last: the
    // base centre (0, 0, 1). The axis is +Z.
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> triangles;  // counter-clockwise seen from outside
    std::vector<std::uint32_t> lines;      // apex-to-ring edges and the ring, for wireframes
};

// slices >= 3; throws std::invalid_argument ("makeLightVolumeCone(): ...") otherwise.
ConeMesh makeLightVolumeCone(int slices = kConeVolumeSlices);

// Factor to scale the ring's radius by so that every side face lies outside the true circular
// cone of radius 1 at z = 1 (the polygon's inscribed circle then has radius >= 1): measured from
// the actual faces, 1 / cos(pi / slices) for a regular ring.
float coneRadialScale(ConeMesh const& mesh);

// Which mesh a light's volume uses: none (directional, or no radius), the sphere, or the cone
// (spots up to kConeVolumeMaxOuterDeg).
enum class VolumeShape { None, Sphere, Cone };
VolumeShape volumeShape(PointLight const& light);

// Where the unit cone lands for a spot: apex at the light, +Z along its direction, height =
// radius (the farthest the light reaches along its axis) and ring radius = height * tan(outer) *
// radialScale; `scale` is PipelineSettings::volumeScale. The spherical sector the spot lights
// (within outer of the axis, closer than the radius) lies inside.
struct ConeVolume {
    glm::vec3 apex{0.0f};
    glm::vec3 axis{0.0f, 0.0f, 1.0f};  // unit
    float height = 0.0f;
    float ringRadius = 0.0f;  // the base ring's vertices' distance from the axis
};
ConeVolume coneVolume(PointLight const& light, float radius, float radialScale, float scale);

// The two unit vectors across `axis` the ring's x and y run along (light_volume.vert's coneBasis).
void coneBasis(glm::vec3 axis, glm::vec3& x, glm::vec3& y);

// A unit-cone vertex in the world.
glm::vec3 coneVertexToWorld(ConeVolume const& cone, glm::vec3 unit);

// Whether the camera's near plane may cut into the cone's mesh (the `flip` partition): the eye is
// closer than nearCornerDistance to the solid circular cone through the ring's vertices, which
// holds the mesh. The cone's own test, not the sphere's.
bool coneMayContainCamera(glm::vec3 eye, ConeVolume const& cone, float nearCornerDistance);

// The wireframes' arrow for a directional light: a shaft from the origin to (0, 0, 1) and a
// four-line head, as a line list (light_volume.vert turns +Z to the light's direction).
struct ArrowMesh {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> lines;
};
ArrowMesh makeDirectionArrow();

}  // namespace gbl
