// Packing and uploading the light list.
#include "gpu/light_buffer.h"

#include "core/light_math.h"
#include "core/octahedral.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gbl {

namespace {
// The texels into the rows of a 2D texture kLightTexelsPerRow wide (no buffer textures: WebGL2).
void uploadRowsTo(gl::Texture& texture, std::vector<glm::vec4>& texels) {
    int const rows = int((texels.size() + kLightTexelsPerRow - 1) / kLightTexelsPerRow);
    texels.resize(std::size_t(rows) * kLightTexelsPerRow, glm::vec4(0.0f));
    if (!texture || texture.height() < rows) {
        texture = gl::Texture::create2D(GL_RGBA32F, kLightTexelsPerRow, rows, "lights.rows");
        texture.setFilter(GL_NEAREST, GL_NEAREST);
    }
    glBindTexture(GL_TEXTURE_2D, texture.id());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kLightTexelsPerRow, rows, GL_RGBA, GL_FLOAT, texels.data());
    glBindTexture(GL_TEXTURE_2D, 0);
}
}  // namespace

float packWireColor(glm::vec3 color) {
    glm::vec3 const c = glm::round(glm::clamp(color, 0.0f, 1.0f) * 255.0f);
    return c.r + 256.0f * c.g + 65536.0f * c.b;
}

std::vector<glm::vec4> packLights(std::span<PointLight const> lights) {
    std::vector<glm::vec4> texels;
    texels.reserve(lights.size() * kTexelsPerLight);
    for (auto const& l : lights) {
        LightRadius const r = lightRadius(l);
        bool const local = isLocalLight(l);
        float const cutoff = r.kind == RadiusKind::Zero || !local ? 0.0f : attenuationCutoff(l, r.radius);
        SpotCone const cone = spotCone(l);
        bool const validDirection = glm::dot(l.direction, l.direction) > 0.0f && std::isfinite(l.direction.x) &&
                                    std::isfinite(l.direction.y) && std::isfinite(l.direction.z);
        glm::vec2 const dir = octEncode(validDirection ? l.direction : glm::vec3(0.0f, -1.0f, 0.0f));
        texels.emplace_back(l.position, local ? r.radius : 0.0f);
        texels.emplace_back(l.color * l.intensity, cutoff);
        texels.emplace_back(l.kc, l.kl, l.kq, cone.cosOuter);
        texels.emplace_back(packWireColor(l.color), dir.x, dir.y, cone.scale);
    }
    return texels;
}

std::optional<std::string> LightBuffer::upload(std::span<PointLight const> lights, GlCaps const& caps) {
    GLint maxTexels = caps.maxTextureBufferTexels;
    if (!gl::kBufferTextures)
        maxTexels = GLint(std::min<long long>(std::numeric_limits<GLint>::max(),
                                              (long long)kLightTexelsPerRow * std::max(caps.maxTextureSize, 1)));
    int const fits = lightsInTexels(maxTexels);
    std::optional<std::string> why;
    if (int(lights.size()) > fits) {
        why = "this context's buffer textures hold " + std::to_string(maxTexels) + " texels (" + std::to_string(fits) +
              " lights); only the first " + std::to_string(fits) + " of " + std::to_string(lights.size()) +
              " lights are shaded";
        lights = lights.first(std::size_t(fits));
    }
    std::vector<glm::vec4> texels = packLights(lights);
    // A buffer texture over an empty buffer is invalid, so keep at least one light's worth.
    if (texels.empty()) texels.resize(kTexelsPerLight, glm::vec4(0.0f));
    if (!gl::kBufferTextures) {
        uploadRowsTo(texture, texels);
    } else if (std::size_t const bytes = texels.size() * sizeof(glm::vec4); !buffer || buffer.size() < bytes) {
        buffer = gl::Buffer::create(GL_TEXTURE_BUFFER, bytes, texels.data(), GL_DYNAMIC_DRAW, "lights");
        texture = gl::Texture::createBuffer(GL_RGBA32F, buffer.id(), "lights.tbo");
    } else {
        buffer.upload(bytes, texels.data());
    }
    count = int(lights.size());
    directional.clear();
    int skipped = 0;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        if (isLocalLight(lights[i]) || validateLight(lights[i])) continue;  // an invalid light shades nothing
        if (int(directional.size()) < kMaxDirectionalLights)
            directional.push_back(int(i));
        else
            ++skipped;
    }
    if (skipped > 0 && !why)
        why = std::to_string(skipped) + " directional lights past the first " + std::to_string(kMaxDirectionalLights) +
              " are not shaded";
    return why;
}

}  // namespace gbl
