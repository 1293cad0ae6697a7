// Procedural meshes (box, plane, cylinder, arch, sphere, torus) with UV-consistent tangents.
#pragma once

#include "scene/scene_data.h"

#include <glm/glm.hpp>

namespace gbl {

// Conventions shared by every builder here, and relied on by the normal-mapping shader:
// - triangles wind counter-clockwise seen from the side the normal points to;
// - normals are unit length; tangent.xyz is unit, orthogonal to the normal and points along
//   dP/du (the direction in which the texture's u grows);
// - tangent.w is the sign that makes cross(normal, tangent.xyz) * w point along dP/dv, so a
//   normal map's green channel bends the normal towards growing v (growing image rows);
// - UVs are in world units times uvScale, so one texture density fits meshes of any size.

// Axis-aligned box of the given full size centred on the origin. Each face's UV starts at 0
// in its corner; uvScale = 1 / size shows the whole texture once on a square face.
// Side faces run u to the right and v downwards as seen from outside.
MeshData makeBox(glm::vec3 size, float uvScale = 1.0f);

// Plane in XZ facing +Y, centred on the origin, split into segX x segZ quads.
// u grows with +X, v with +Z.
MeshData makePlane(glm::vec2 size, int segX = 1, int segZ = 1, float uvScale = 1.0f);

// Cylinder around +Y from y = 0 to y = height; `rings` rows of quads along the height.
// u runs around the side (arc length), v downwards; caps close both ends when asked.
MeshData makeCylinder(float radius, float height, int segments, int rings = 1, float uvScale = 1.0f, bool caps = true);

// The curved part of an arch: a half annulus in the XY plane (centre at the origin, feet on
// y = 0, opening towards -Y) extruded along Z by `depth` (centred on z = 0).
// With squareOuter the outer outline is the rectangle [-outer, outer] x [0, outer] instead of
// a half circle, which fills the spandrels so arches can sit side by side under a beam.
// segments is rounded up to a multiple of 4 so the rectangle's corners fall on vertices.
MeshData makeArch(float innerRadius, float outerRadius, float depth, int segments, float uvScale = 1.0f,
                  bool squareOuter = false);

// UV sphere centred on the origin; u runs around (longitude), v from the north pole down.
MeshData makeSphere(float radius, int slices, int stacks, float uvScale = 1.0f);

// Torus around +Y in the XZ plane: ring radius majorRadius, tube radius minorRadius.
MeshData makeTorus(float majorRadius, float minorRadius, int majorSegments, int minorSegments, float uvScale = 1.0f);

// Applies an affine transform: positions by m, normals by its inverse transpose, tangents by
// m then re-orthogonalised. A mirroring transform flips tangent.w and the winding.
void transformMesh(MeshData& mesh, glm::mat4 const& m);

// Appends src (transformed by m) to dst; dst keeps its name and material.
void appendMesh(MeshData& dst, MeshData const& src, glm::mat4 const& m = glm::mat4(1.0f));

}  // namespace gbl
