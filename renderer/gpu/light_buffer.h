// Lights as the shaders read them: four RGBA32F texels per light in a buffer texture.
//   texel 0: position.xyz, radius (0 for directional lights: every local test rejects them)
//   texel 1: colour * intensity, cutoff (windowed-attenuation offset = threshold / Imax)
//   texel 2: Kc, Kl, Kq, spot cosOuter (-2 for other kinds: no cone)
//   texel 3: wire colour (8 bits a channel as the integer r + 256 g + 65536 b, exact in a float;
//            for light cubes and wireframes), octahedral direction (2 numbers), spot cone scale
// Directional lights are also listed (indices, at most kMaxDirectionalLights) for the global
// loop every mode runs (shadeGlobalLights in shaders/light_fetch.glsl); more are left unshaded and
// upload() says so.
#pragma once

#include "core/point_light.h"
#include "gl/buffer.h"
#include "gl/caps.h"
#include "gl/gl_api.h"
#include "gl/texture.h"

#include <glm/glm.hpp>

#include <algorithm>

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace gbl {

inline constexpr int kTexelsPerLight = 4;
// Where buffer textures are missing (gl::kBufferTextures, WebGL2) the texels fill the rows of a 2D
// RGBA32F texture gl::kLightTexelsPerRow wide, left to right and top to bottom (shaders/light_texels.glsl).
inline constexpr int kLightTexelsPerRow = gl::kLightTexelsPerRow;

// The wire colour of texel 3: each channel rounded to 8 bits, packed as r + 256 g + 65536 b.
float packWireColor(glm::vec3 color);

// Packs the lights in order; a light with radius 0 (invalid or too dim) keeps its slot with
// radius 0 so indices match the caller's list, and shades nothing.
std::vector<glm::vec4> packLights(std::span<PointLight const> lights);

struct LightBuffer {
    gl::Buffer buffer;
    gl::Texture texture;  // GL_TEXTURE_BUFFER over `buffer`, RGBA32F (or the 2D texture, above)
    int count = 0;
    std::vector<int> directional;  // indices of the directional lights shaded, in list order

    // Uploads every light the context's buffer textures can address (GL_MAX_TEXTURE_BUFFER_SIZE
    // texels, kTexelsPerLight per light; 65,536 texels = 16,384 lights is all GL guarantees,
    // drivers give millions). Beyond that, the first lights that fit are kept and the reason is
    // returned, so the frame says why lights are missing rather than reading past the buffer.
    // The limits come from GlCaps, read once at start-up.
    std::optional<std::string> upload(std::span<PointLight const> lights, GlCaps const& caps);
};

// How many lights fit in a buffer texture of `maxTexels` texels.
inline int lightsInTexels(long long maxTexels) {
    return int(std::min<long long>(maxTexels / kTexelsPerLight, kMaxLights));
}

}  // namespace gbl
