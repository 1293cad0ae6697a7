// Packing and uploading the light list.
#include "gpu/light_buffer.h"

#include "core/light_math.h"

namespace gbl {

std::vector<glm::vec4> packLights(std::span<PointLight const> lights) {
    std::vector<glm::vec4> texels;
    texels.reserve(lights.size() * kTexelsPerLight);
    for (auto const& l : lights) {
        LightRadius const r = lightRadius(l);
        float const cutoff = r.kind == RadiusKind::Zero ? 0.0f : attenuationCutoff(l, r.radius);
        texels.emplace_back(l.position, r.radius);
        texels.emplace_back(l.color * l.intensity, cutoff);
        texels.emplace_back(l.kc, l.kl, l.kq, 0.0f);
        texels.emplace_back(l.color, 0.0f);
    }
    return texels;
}

std::optional<std::string> LightBuffer::upload(std::span<PointLight const> lights) {
    GLint maxTexels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
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
    std::size_t const bytes = texels.size() * sizeof(glm::vec4);
    if (!buffer || buffer.size() < bytes) {
        buffer = gl::Buffer::create(GL_TEXTURE_BUFFER, bytes, texels.data(), GL_DYNAMIC_DRAW, "lights");
        texture = gl::Texture::createBuffer(GL_RGBA32F, buffer.id(), "lights.tbo");
    } else {
        buffer.upload(bytes, texels.data());
    }
    count = int(lights.size());
    return why;
}

}  // namespace gbl
