// Deterministic generated textures: albedo, tangent-space normal and specular maps.
#pragma once

#include "scene/scene_data.h"

#include <cstdint>
#include <span>
#include <string>

namespace gbl {

// The three maps of one surface, all tileable in both directions.
struct TextureSet {
    ImageData albedo;    // RGBA, srgb = true
    ImageData normal;    // RGBA, srgb = false, tangent space: n * 0.5 + 0.5, +Z out of the surface
    ImageData specular;  // 1 channel, srgb = false, specular intensity 0..1
};

// Our own integer hash and the noise built on it: std:: distributions differ between standard
// libraries, these give the same bits everywhere.
std::uint32_t hashU32(std::uint32_t x);
float hashUnit(int x, int y, std::uint32_t seed);  // in [0, 1)

// Value noise on a lattice that repeats every `period` cells, in [0, 1]; x and y in cells.
float tiledValueNoise(float x, float y, int period, std::uint32_t seed);
// Sum of `octaves` layers of tiledValueNoise, each at twice the frequency and half the
// amplitude, normalised to [0, 1]; x and y in [0, 1) tile.
float tiledFbm(float x, float y, int basePeriod, int octaves, std::uint32_t seed);

// Tangent-space normal map from a height field (row-major, rows top to bottom, wrapping at the
// edges). Heights are in texels times `strength`: n = normalize(-s dh/dx, -s dh/dy, 1) by
// central differences, where x grows with u (the tangent) and y with v (the bitangent).
// A flat region encodes (128, 128, 255).
ImageData normalMapFromHeight(std::span<float const> height, int width, int heightPx, float strength, std::string name);

// Surfaces of the default scene. size is the edge in texels (a power of two >= 64).
TextureSet makeBrickTextures(int size, std::uint32_t seed);      // red brick, running bond, 8 courses
TextureSet makeFlagstoneTextures(int size, std::uint32_t seed);  // 4 x 4 grey-beige paving stones
TextureSet makeSandstoneTextures(int size, std::uint32_t seed);  // warm dressed stone, 2 ashlar courses
TextureSet makeWoodTextures(int size, std::uint32_t seed);       // 4 vertical planks with grain

}  // namespace gbl
