// Lights as the shaders read them: four RGBA32F texels per light in a buffer texture.
//   texel 0: position.xyz, radius
//   texel 1: colour * intensity, cutoff (windowed-attenuation offset = threshold / Imax)
//   texel 2: Kc, Kl, Kq, 0
//   texel 3: colour (0..1, for light cubes and wireframes), 0
#pragma once

#include "core/point_light.h"
#include "gl/buffer.h"
#include "gl/texture.h"

#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace gbl {

inline constexpr int kTexelsPerLight = 4;

// Packs the lights in order; a light with radius 0 (invalid or too dim) keeps its slot with
// radius 0 so indices match the caller's list, and shades nothing.
std::vector<glm::vec4> packLights(std::span<PointLight const> lights);

struct LightBuffer {
    gl::Buffer buffer;
    gl::Texture texture;  // GL_TEXTURE_BUFFER over `buffer`, RGBA32F
    int count = 0;

    void upload(std::span<PointLight const> lights);
};

}  // namespace gbl
