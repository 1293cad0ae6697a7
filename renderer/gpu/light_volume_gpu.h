// GPU resources of the light-volume passes: the sphere mesh and the spot lights' cone mesh
// (triangles and wireframe lines each) and the per-frame list of lights to draw, partitioned by
// mesh and for the `flip` cull mode.
#pragma once

#include "gl/buffer.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"

namespace gbl {

struct LightVolumeGpu {
    gl::VertexArray triangleVao;  // unit sphere, triangle index list
    gl::VertexArray lineVao;      // same vertices, line index list (wireframes)
    gl::Buffer vertices;
    gl::Buffer triangles;
    gl::Buffer lines;
    GLsizei triangleIndexCount = 0;
    GLsizei lineIndexCount = 0;
    float meshEnclosingScale = 1.0f;  // enclosingScale() of the mesh
    // What the volumes are drawn at this frame: meshEnclosingScale * PipelineSettings::volumeScale.
    float enclosingScale = 1.0f;

    // The cone (core/light_volume_cone.h), placed per spot by light_volume.vert.
    gl::VertexArray coneTriangleVao;
    gl::VertexArray coneLineVao;
    gl::Buffer coneVertices;
    gl::Buffer coneTriangles;
    gl::Buffer coneLines;
    GLsizei coneTriangleIndexCount = 0;
    GLsizei coneLineIndexCount = 0;
    float coneRadialScale = 1.0f;  // coneRadialScale() of the mesh
    // The directional lights' arrow (wireframes only), one instance per directional light.
    gl::VertexArray arrowVao;
    gl::Buffer arrowVertices;
    gl::Buffer arrowLines;
    GLsizei arrowLineIndexCount = 0;
    float volumeScale = 1.0f;  // PipelineSettings::volumeScale this frame (the cone's share)

    // Light indices to draw this frame (radius > 0 only), as an R32I buffer texture: the sphere
    // lights (first those whose volume cannot contain the camera, then the ones that may), then
    // the cone lights in the same two groups.
    gl::Buffer instances;
    gl::Texture instancesTbo;
    int outsideCount = 0;  // sphere lights
    int insideCount = 0;
    int coneOutsideCount = 0;  // cone lights, from slot outsideCount + insideCount on
    int coneInsideCount = 0;
    int sphereCount() const { return outsideCount + insideCount; }
    int totalCount() const { return sphereCount() + coneOutsideCount + coneInsideCount; }

    explicit operator bool() const { return bool(triangleVao); }
};

// Uploads the sphere of core/light_volume_mesh.h (instances stay empty until a frame fills them).
LightVolumeGpu createLightVolumeGpu();

}  // namespace gbl
