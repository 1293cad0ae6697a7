// Geometry fix-ups the glTF loader applies to a primitive: flat normals and generated tangents.
#pragma once

#include "scene/scene_data.h"

namespace gbl {

// Gives every triangle its own three vertices carrying the face normal, so a mesh without
// NORMAL data shades as facets (glTF 2.0, "Meshes": flat normals when normals are missing).
// Degenerate triangles get +Z. Indices become 0..n-1.
void generateFlatNormals(MeshData& mesh);

// Per-triangle dP/du accumulated at each vertex, then made orthogonal to the vertex normal.
// tangent.w is chosen so that cross(normal, tangent.xyz) * w points along -dP/dv: glTF's v
// grows down the image while a normal map's +Y (green) points up it, so this is the handedness
// of the TANGENT data glTF files carry (the shader treats both alike). Note mesh_builder.h's
// procedural meshes use +dP/dv with their own textures. Vertices whose triangles have
// degenerate UVs get any unit vector perpendicular to the normal.
void generateTangents(MeshData& mesh);

}  // namespace gbl
