// Geometry fix-ups the glTF loader applies to a primitive: strips and fans as lists, flat normals, tangents.
#pragma once

#include "scene/scene_data.h"

#include <cstdint>
#include <vector>

namespace gbl {

enum class TriangleMode { List, Strip, Fan };

// The triangle list a primitive's vertex sequence (its indices, or 0..n-1) draws, with glTF 2.0's
// vertex order ("Meshes", primitive modes): strip triangle i is (v[i], v[i+1+i%2], v[i+2-i%2]),
// so every triangle keeps the first one's winding; fan triangle i is (v[i+1], v[i+2], v[0]).
// Triangles with a repeated vertex (the zero-area joints of stitched strips) are dropped. A list
// keeps only whole triangles.
std::vector<std::uint32_t> triangleList(TriangleMode mode, std::vector<std::uint32_t> const& sequence);

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
// `texCoord` picks the set the normal map reads (1 = Vertex::uv1).
void generateTangents(MeshData& mesh, int texCoord = 0);

}  // namespace gbl
