// A G-buffer another program wrote, decoded and ready to upload for re-lighting
// (Renderer::setImportedGBuffer; renderer/import/relight_frame.h builds it from an ImportedGBuffer).
// Plain values, no GL.
#pragma once

#include <glm/glm.hpp>

#include <cstddef>
#include <vector>

namespace gbl {

struct ImportedFrame {
    int width = 0;
    int height = 0;
    // Per pixel, rows bottom to top as GL textures store them (row 0 is the frame's bottom row):
    std::vector<glm::vec4> positionDepth;  // xyz world position, w window depth in [0, 1); 1 = background
    std::vector<glm::vec4> normal;         // xyz unit world normal, w unused
    std::vector<glm::vec4> albedoSpec;     // rgb linear albedo, a specular intensity
    // rgb emitted radiance (linear), a ambient occlusion; empty: emission 0 and occlusion 1 everywhere
    // (kNoEmissiveAo), what a manifest without emissive and occlusion gives.
    std::vector<glm::vec4> emissiveAo;
    // The camera the G-buffer was drawn with (OpenGL conventions: view space looks down -z).
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::vec3 eye{0.0f};
    float nearPlane = 0.1f;
    float farPlane = 100.0f;

    std::size_t pixelCount() const { return std::size_t(width) * std::size_t(height); }
};

}  // namespace gbl
