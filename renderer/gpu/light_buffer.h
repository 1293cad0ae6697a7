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

#include <algorithm>

#include <optional>
#include <span>
#include <string>
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

    // Uploads every light the context's buffer textures can address (GL_MAX_TEXTURE_BUFFER_SIZE
    // texels, kTexelsPerLight per light; 65,536 texels = 16,384 lights is all GL guarantees,
    // drivers give millions). Beyond that, the first lights that fit are kept and the reason is
    // returned, so the frame says why lights are missing rather than reading past the buffer.
    std::optional<std::string> upload(std::span<PointLight const> lights);
};

// How many lights fit in a buffer texture of `maxTexels` texels.
inline int lightsInTexels(long long maxTexels) {
    return int(std::min<long long>(maxTexels / kTexelsPerLight, kMaxLights));
}

}  // namespace gbl
