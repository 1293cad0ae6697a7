// KHR_texture_transform as a value and its UV matrix: pure math shared by the loader, the GPU upload and tests.
#pragma once

#include <glm/glm.hpp>

#include <cmath>

namespace gbl {

// How one texture of a material reads its coordinates: which TEXCOORD set, then an affine
// transform of those coordinates (KHR_texture_transform; identity and set 0 without it).
struct TextureTransform {
    glm::vec2 offset{0.0f};
    float rotation = 0.0f;  // radians, counter-clockwise in glTF's UV space (u right, v down)
    glm::vec2 scale{1.0f};
    int texCoord = 0;  // 0 = TEXCOORD_0, 1 = TEXCOORD_1

    bool operator==(TextureTransform const&) const = default;
    bool isIdentity() const { return offset == glm::vec2(0.0f) && rotation == 0.0f && scale == glm::vec2(1.0f); }
};

// translation * rotation * scale, applied to (u, v, 1). The rotation is the one the extension's
// sample model (TextureTransformTest) and its worked example define: with v pointing down the
// image, a positive angle turns +u towards -v, i.e. u' = c u + s v, v' = -s u + c v. (The
// extension's first GLSL listing had the standard y-up matrix, which turns the other way; the
// Khronos group corrected it, glTF issue 1563.) Check: offset (0, 1), rotation pi/2, scale 0.5
// maps the unit square onto the lower-left quadrant of the image, as the extension says.
inline glm::mat3 textureTransformMatrix(TextureTransform const& t) {
    float const c = std::cos(t.rotation), s = std::sin(t.rotation);
    glm::mat3 const translation(1, 0, 0, 0, 1, 0, t.offset.x, t.offset.y, 1);  // glm is column-major
    glm::mat3 const rotation(c, -s, 0, s, c, 0, 0, 0, 1);
    glm::mat3 const scale(t.scale.x, 0, 0, 0, t.scale.y, 0, 0, 0, 1);
    return translation * rotation * scale;
}

inline glm::vec2 applyTextureTransform(TextureTransform const& t, glm::vec2 uv) {
    return glm::vec2(textureTransformMatrix(t) * glm::vec3(uv, 1.0f));
}

}  // namespace gbl
