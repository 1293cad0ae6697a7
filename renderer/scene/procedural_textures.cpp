// Generated surface textures: each surface is a per-texel function of colour, height and
// specular; the normal map is derived from the height so bumps and colour always agree.
#include "scene/procedural_textures.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace gbl {

std::uint32_t hashU32(std::uint32_t x) {
    // Integer avalanche mix (xor-shift / multiply rounds).
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

float hashUnit(int x, int y, std::uint32_t seed) {
    std::uint32_t const h = hashU32(std::uint32_t(x) * 0x9e3779b1U ^ hashU32(std::uint32_t(y) + seed * 0x85ebca77U));
    return float(h >> 8) * (1.0f / 16777216.0f);  // 24 bits: exact in a float, never 1
}

namespace {

int wrap(int i, int n) {
    return ((i % n) + n) % n;
}
float fract(float x) {
    return x - std::floor(x);
}
float smooth01(float t) {
    return t * t * (3.0f - 2.0f * t);
}

// Value noise whose lattice repeats every periodX cells along x and periodY along y.
float noise2(float x, float y, int periodX, int periodY, std::uint32_t seed) {
    float const fx = std::floor(x), fy = std::floor(y);
    int const x0 = int(fx), y0 = int(fy);
    float const tx = smooth01(x - fx), ty = smooth01(y - fy);
    auto at = [&](int i, int j) { return hashUnit(wrap(i, periodX), wrap(j, periodY), seed); };
    float const a = at(x0, y0), b = at(x0 + 1, y0), c = at(x0, y0 + 1), d = at(x0 + 1, y0 + 1);
    return glm::mix(glm::mix(a, b, tx), glm::mix(c, d, tx), ty);
}

// Fractal sum over a tile: u, v in [0, 1), anisotropic base periods.
float fbm2(float u, float v, int periodX, int periodY, int octaves, std::uint32_t seed) {
    float sum = 0.0f, amp = 1.0f, total = 0.0f;
    for (int o = 0; o < octaves; ++o) {
        sum += amp * noise2(u * float(periodX), v * float(periodY), periodX, periodY, seed + std::uint32_t(o) * 101U);
        total += amp;
        amp *= 0.5f;
        periodX *= 2;
        periodY *= 2;
    }
    return sum / total;
}

struct Texel {
    glm::vec3 color;  // sRGB-encoded 0..1
    float height;     // 0..1
    float specular;   // 0..1
};

std::uint8_t toByte(float v) {
    return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

// Evaluates texelAt(u, v) at every texel centre and packs the three maps.
template <class F>
TextureSet generate(int size, std::string const& name, float normalStrength, F&& texelAt) {
    size = std::max(size, 8);
    std::size_t const n = std::size_t(size) * std::size_t(size);
    TextureSet set;
    set.albedo = {name + "_albedo", size, size, 4, true, std::vector<std::uint8_t>(n * 4)};
    set.specular = {name + "_specular", size, size, 1, false, std::vector<std::uint8_t>(n)};
    std::vector<float> height(n);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            std::size_t const i = std::size_t(y) * std::size_t(size) + std::size_t(x);
            Texel const t = texelAt((float(x) + 0.5f) / float(size), (float(y) + 0.5f) / float(size));
            for (int c = 0; c < 3; ++c) set.albedo.pixels[i * 4 + std::size_t(c)] = toByte(t.color[c]);
            set.albedo.pixels[i * 4 + 3] = 255;
            set.specular.pixels[i] = toByte(t.specular);
            height[i] = t.height;
        }
    }
    set.normal = normalMapFromHeight(height, size, size, normalStrength, name + "_normal");
    return set;
}

// Distance (in tile units) from (lx, ly) inside a w x h cell to the cell's nearest edge.
float edgeDistance(float lx, float ly, float w, float h) {
    return std::min(std::min(lx, 1.0f - lx) * w, std::min(ly, 1.0f - ly) * h);
}

}  // namespace

float tiledValueNoise(float x, float y, int period, std::uint32_t seed) {
    period = std::max(period, 1);
    return noise2(x, y, period, period, seed);
}

float tiledFbm(float x, float y, int basePeriod, int octaves, std::uint32_t seed) {
    return fbm2(x, y, std::max(basePeriod, 1), std::max(basePeriod, 1), std::max(octaves, 1), seed);
}

ImageData normalMapFromHeight(std::span<float const> height, int width, int heightPx, float strength,
                              std::string name) {
    ImageData img{std::move(name), width, heightPx, 4, false, {}};
    if (width <= 0 || heightPx <= 0 || height.size() < std::size_t(width) * std::size_t(heightPx)) {
        img.width = img.height = 0;
        return img;
    }
    img.pixels.resize(std::size_t(width) * std::size_t(heightPx) * 4);
    auto h = [&](int x, int y) {
        return height[std::size_t(wrap(y, heightPx)) * std::size_t(width) + std::size_t(wrap(x, width))];
    };
    for (int y = 0; y < heightPx; ++y) {
        for (int x = 0; x < width; ++x) {
            float const dx = (h(x + 1, y) - h(x - 1, y)) * 0.5f;
            float const dy = (h(x, y + 1) - h(x, y - 1)) * 0.5f;
            glm::vec3 const n = glm::normalize(glm::vec3(-strength * dx, -strength * dy, 1.0f));
            std::size_t const i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
            for (int c = 0; c < 3; ++c) img.pixels[i + std::size_t(c)] = toByte(n[c] * 0.5f + 0.5f);
            img.pixels[i + 3] = 255;
        }
    }
    return img;
}

TextureSet makeBrickTextures(int size, std::uint32_t seed) {
    // Running bond: 8 courses of 4 bricks per tile, every other course shifted half a brick.
    return generate(size, "brick", 0.012f * float(size), [&](float u, float v) {
        int const row = int(std::floor(v * 8.0f));
        float const bx = fract(u + (row % 2 ? 0.125f : 0.0f)) * 4.0f;
        int const col = int(std::floor(bx));
        float const edge = edgeDistance(fract(bx), fract(v * 8.0f), 0.25f, 0.125f) - 0.006f;
        float const fine = fbm2(u, v, 32, 32, 3, seed);
        float const grit = noise2(u * 128.0f, v * 128.0f, 128, 128, seed + 7U);
        if (edge < 0.0f) {  // mortar joint
            float const m = 0.85f + 0.2f * grit;
            return Texel{glm::vec3(0.62f, 0.60f, 0.55f) * m, 0.1f * fine, 0.04f};
        }
        float const pick = hashUnit(col, row, seed + 1U);
        glm::vec3 base = glm::mix(glm::vec3(0.55f, 0.22f, 0.14f), glm::vec3(0.72f, 0.36f, 0.22f), pick);
        if (hashUnit(col, row, seed + 2U) < 0.15f) base *= 0.6f;  // a few over-fired bricks
        float const bevel = smooth01(std::min(edge / 0.012f, 1.0f));
        float const h = 0.45f + 0.45f * bevel + 0.12f * (fine - 0.5f) + 0.04f * grit;
        return Texel{base * (0.8f + 0.35f * fine + 0.1f * grit), h, 0.1f + 0.15f * fine};
    });
}

TextureSet makeFlagstoneTextures(int size, std::uint32_t seed) {
    return generate(size, "flagstone", 0.01f * float(size), [&](float u, float v) {
        int const cx = int(std::floor(u * 4.0f)), cy = int(std::floor(v * 4.0f));
        float const lx = fract(u * 4.0f), ly = fract(v * 4.0f);
        float const edge = edgeDistance(lx, ly, 0.25f, 0.25f) - 0.007f;
        float const fine = fbm2(u, v, 16, 16, 4, seed);
        float const grit = noise2(u * 96.0f, v * 96.0f, 96, 96, seed + 3U);
        if (edge < 0.0f) return Texel{glm::vec3(0.28f, 0.27f, 0.25f) * (0.8f + 0.3f * grit), 0.05f * grit, 0.05f};
        float const pick = hashUnit(cx, cy, seed + 1U);
        glm::vec3 const base = glm::mix(glm::vec3(0.52f, 0.51f, 0.49f), glm::vec3(0.68f, 0.61f, 0.50f), pick);
        // Each stone is laid slightly out of level.
        float const tiltX = hashUnit(cx, cy, seed + 4U) - 0.5f, tiltY = hashUnit(cx, cy, seed + 5U) - 0.5f;
        float const bevel = smooth01(std::min(edge / 0.02f, 1.0f));
        float const h = 0.4f + 0.4f * bevel + 0.1f * (fine - 0.5f) + 0.08f * (tiltX * lx + tiltY * ly);
        float const wear = std::clamp((fine - 0.35f) * 2.5f, 0.0f, 1.0f);  // polished where walked on
        return Texel{base * (0.75f + 0.4f * fine + 0.08f * grit), h, 0.1f + 0.45f * wear};
    });
}

TextureSet makeSandstoneTextures(int size, std::uint32_t seed) {
    return generate(size, "sandstone", 0.008f * float(size), [&](float u, float v) {
        int const course = int(std::floor(v * 2.0f));
        float const bx = fract(u + (course % 2 ? 0.5f : 0.0f));
        float const joint =
            std::min({std::min(bx, 1.0f - bx), fract(v * 2.0f) * 0.5f, (1.0f - fract(v * 2.0f)) * 0.5f}) - 0.004f;
        float const layers = fbm2(u, v, 2, 24, 3, seed);  // sediment bands run horizontally
        float const grain = fbm2(u, v, 32, 32, 4, seed + 11U);
        float const pits = noise2(u * 160.0f, v * 160.0f, 160, 160, seed + 13U);  // tooling marks
        if (joint < 0.0f) return Texel{glm::vec3(0.55f, 0.47f, 0.36f), 0.0f, 0.03f};
        glm::vec3 const base = glm::mix(glm::vec3(0.72f, 0.60f, 0.43f), glm::vec3(0.86f, 0.76f, 0.58f), layers);
        float const bevel = smooth01(std::min(joint / 0.01f, 1.0f));
        float const h = 0.5f + 0.3f * bevel + 0.5f * (grain - 0.5f) + 0.08f * pits;
        return Texel{base * (0.85f + 0.25f * grain - 0.06f * pits), h, 0.1f + 0.2f * grain};
    });
}

TextureSet makeWoodTextures(int size, std::uint32_t seed) {
    return generate(size, "wood", 0.01f * float(size), [&](float u, float v) {
        float const px = u * 4.0f;
        int const plank = int(std::floor(px));
        float const lx = fract(px);
        float const gap = std::min(lx, 1.0f - lx) * 0.25f - 0.005f;
        if (gap < 0.0f) return Texel{glm::vec3(0.12f, 0.08f, 0.05f), 0.0f, 0.02f};
        // Grain: stretched noise bends rings that run along the plank (along v).
        float const warp = fbm2(u, v, 8, 2, 3, seed + std::uint32_t(plank));
        float const rings = 0.5f + 0.5f * std::sin((lx * 7.0f + warp * 6.0f + float(plank)) * 6.2831853f);
        float const fibre = fbm2(u, v, 64, 4, 2, seed + 17U);
        glm::vec3 const base =
            glm::mix(glm::vec3(0.42f, 0.26f, 0.14f), glm::vec3(0.62f, 0.42f, 0.24f), hashUnit(plank, 0, seed + 1U));
        float const bevel = smooth01(std::min(gap / 0.01f, 1.0f));
        float const h = 0.5f + 0.35f * bevel + 0.06f * rings + 0.05f * fibre;
        return Texel{base * (0.7f + 0.25f * rings + 0.2f * fibre), h, 0.15f + 0.15f * rings};
    });
}

}  // namespace gbl
