// GPU resources of the light-volume passes: the sphere mesh (triangles and wireframe lines) and
// the per-frame list of lights to draw, partitioned for the `flip` cull mode.
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

    // Light indices to draw this frame (radius > 0 only), as an R32I buffer texture: first the
    // lights whose volume cannot contain the camera, then the ones that may.
    gl::Buffer instances;
    gl::Texture instancesTbo;
    int outsideCount = 0;
    int insideCount = 0;

    explicit operator bool() const { return bool(triangleVao); }
};

// Uploads the sphere of core/light_volume_mesh.h (instances stay empty until a frame fills them).
LightVolumeGpu createLightVolumeGpu();

}  // namespace gbl
