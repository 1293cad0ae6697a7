// Uploading the light-volume sphere.
#include "gpu/light_volume_gpu.h"

#include "core/light_volume_cone.h"
#include "core/light_volume_mesh.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace gbl {

LightVolumeGpu createLightVolumeGpu() {
    LightVolumeGpu v;
    SphereMesh const mesh = makeLightVolumeSphere();
    v.meshEnclosingScale = v.enclosingScale = enclosingScale(mesh);
    v.vertices = gl::Buffer::create(GL_ARRAY_BUFFER, mesh.positions.size() * sizeof(glm::vec3), mesh.positions.data(),
                                    GL_STATIC_DRAW, "light volume.vertices");
    v.triangles = gl::Buffer::create(GL_ELEMENT_ARRAY_BUFFER, mesh.triangles.size() * sizeof(std::uint32_t),
                                     mesh.triangles.data(), GL_STATIC_DRAW, "light volume.triangles");
    v.lines = gl::Buffer::create(GL_ELEMENT_ARRAY_BUFFER, mesh.lines.size() * sizeof(std::uint32_t), mesh.lines.data(),
                                 GL_STATIC_DRAW, "light volume.lines");
    v.triangleIndexCount = GLsizei(mesh.triangles.size());
    v.lineIndexCount = GLsizei(mesh.lines.size());
    auto makeVao = [&](gl::VertexArray& vao, gl::Buffer const& vertices, gl::Buffer const& indices, char const* label) {
        vao = gl::VertexArray::create(label);
        glBindVertexArray(vao.id());
        glBindBuffer(GL_ARRAY_BUFFER, vertices.id());
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices.id());
        glBindVertexArray(0);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
    };
    makeVao(v.triangleVao, v.vertices, v.triangles, "light volume");
    makeVao(v.lineVao, v.vertices, v.lines, "light volume.wire");

    ConeMesh const cone = makeLightVolumeCone();
    v.coneRadialScale = coneRadialScale(cone);
    v.coneVertices = gl::Buffer::create(GL_ARRAY_BUFFER, cone.positions.size() * sizeof(glm::vec3),
                                        cone.positions.data(), GL_STATIC_DRAW, "light volume cone.vertices");
    v.coneTriangles = gl::Buffer::create(GL_ELEMENT_ARRAY_BUFFER, cone.triangles.size() * sizeof(std::uint32_t),
                                         cone.triangles.data(), GL_STATIC_DRAW, "light volume cone.triangles");
    v.coneLines = gl::Buffer::create(GL_ELEMENT_ARRAY_BUFFER, cone.lines.size() * sizeof(std::uint32_t),
                                     cone.lines.data(), GL_STATIC_DRAW, "light volume cone.lines");
    v.coneTriangleIndexCount = GLsizei(cone.triangles.size());
    v.coneLineIndexCount = GLsizei(cone.lines.size());
    makeVao(v.coneTriangleVao, v.coneVertices, v.coneTriangles, "light volume cone");
    makeVao(v.coneLineVao, v.coneVertices, v.coneLines, "light volume cone.wire");

    ArrowMesh const arrow = makeDirectionArrow();
    v.arrowVertices = gl::Buffer::create(GL_ARRAY_BUFFER, arrow.positions.size() * sizeof(glm::vec3),
                                         arrow.positions.data(), GL_STATIC_DRAW, "light arrow.vertices");
    v.arrowLines = gl::Buffer::create(GL_ELEMENT_ARRAY_BUFFER, arrow.lines.size() * sizeof(std::uint32_t),
                                      arrow.lines.data(), GL_STATIC_DRAW, "light arrow.lines");
    v.arrowLineIndexCount = GLsizei(arrow.lines.size());
    makeVao(v.arrowVao, v.arrowVertices, v.arrowLines, "light arrow");
    return v;
}

}  // namespace gbl
